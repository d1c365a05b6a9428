#include "report/words.h"

#include <cstdio>
#include <stdexcept>

namespace raylab::report {

namespace {

// French typography: a no-break space (U+00A0) before ":" ";" "?" "!", a decimal comma.
#define NBSP "\u00A0"

constexpr Words kEnglish{
    "en",
    "Lab report",
    "Made by `raylab report` from this file, which is yours: write in the framed sections (between the "
    "`raylab:student` markers); a new run keeps them and refreshes everything else. Each figure of the "
    "handout is shown as you rendered it, beside the reference and a map of the difference.",
    "Name",
    "Group",
    "Course",
    "Date",
    "Total grade",
    "%s / %s for the function checks, %s / %s for the figures",
    "Lab",
    "Figure",
    "Yours, the reference, the difference:",
    "render time",
    "Difference scale (LSB, the largest channel difference): %s dark: within tolerance; dark red: just "
    "outside (2 LSB); yellow: %s LSB or more.",
    "A noisy figure: a pixel is within tolerance when it is within %s standard deviations of the reference's noise.",
    "no difference map (no picture to compare)",
    "Grade",
    "Your text",
    "Write here what you did, what the figures show and what went wrong.",
    "Antialiasing: aliased against antialiased",
    "Figure 3(c) (one ray per pixel) beside figure 6 (several samples per pixel), and a close-up of the silhouette.",
    "aliased (figure 3(c))",
    "antialiased (figure 6)",
    "%s: %s samples per pixel, %s rays, %s",
    "Close-up: pixels x %s to %s, y %s to %s of the %s x %s picture, each enlarged %s times.",
    "Kept from the previous version",
    "Text from the previous report.md that `raylab report` could not place (outside the `raylab:student` "
    "markers, or under a marker it no longer writes). Nothing is dropped: move it where it belongs.",
    "From the section `%s`:",
    "Your edit of the generated part `%s` (generated parts are rewritten on every run):",
    "The grader's full report",
    ": ",
    "note: fill in %s (name, group, course) for the report's title block",
    "# The title block of your lab report: fill it once; `raylab report` reads it on every run.\n"
    "name = \"Your name\"\n"
    "group = \"Your group\"\n"
    "course = \"Your course\"\n"
    "date = \"\" # empty: the day of the run (for example \"2026-11-23\")\n",
};

constexpr Words kFrench{
    "fr",
    "Compte rendu de TP",
    "Ce compte rendu est produit par `raylab report` à partir de ce fichier, qui est le vôtre" NBSP
    ": écrivez dans les sections encadrées (entre les marqueurs `raylab:student`)" NBSP
    "; une nouvelle exécution les conserve et met à jour tout le reste. Chaque figure de l'énoncé y est "
    "montrée telle que vous l'avez rendue, à côté de la référence et d'une carte de la différence.",
    "Nom",
    "Groupe",
    "Cours",
    "Date",
    "Note totale",
    "%s / %s pour les vérifications des fonctions, %s / %s pour les figures",
    "TP",
    "Figure",
    "La vôtre, la référence, la différence" NBSP ":",
    "temps de rendu",
    "Échelle de la différence (en LSB, le plus grand écart d'un canal)" NBSP ": %s sombre" NBSP
    ": dans la tolérance" NBSP "; rouge sombre" NBSP ": juste au-delà (2 LSB)" NBSP "; jaune" NBSP ": %s LSB ou plus.",
    "Figure bruitée" NBSP ": un pixel est dans la tolérance quand il est à moins de %s écarts types du bruit de la référence.",
    "pas de carte de la différence (pas d'image à comparer)",
    "Évaluation",
    "Votre texte",
    "Écrivez ici ce que vous avez fait, ce que montrent les figures et ce qui n'a pas marché.",
    "Anticrénelage" NBSP ": sans et avec",
    "La figure 3(c) (un rayon par pixel) à côté de la figure 6 (plusieurs échantillons par pixel), et un gros "
    "plan sur la silhouette.",
    "sans anticrénelage (figure 3(c))",
    "avec anticrénelage (figure 6)",
    "%s" NBSP ": %s échantillons par pixel, %s rayons, %s",
    "Gros plan" NBSP ": pixels x %s à %s, y %s à %s de l'image de %s x %s, chaque pixel agrandi %s fois.",
    "Conservé de la version précédente",
    "Texte du report.md précédent que `raylab report` n'a pas su placer (hors des marqueurs "
    "`raylab:student`, ou sous un marqueur qu'il n'écrit plus). Rien n'est perdu" NBSP ": déplacez-le où il faut.",
    "De la section `%s`" NBSP ":",
    "Votre modification de la partie générée `%s` (les parties générées sont réécrites à chaque exécution)" NBSP ":",
    "Le rapport complet du correcteur",
    NBSP ": ",
    "remarque" NBSP ": remplissez %s (nom, groupe, cours) pour l'en-tête du compte rendu",
    "# L'en-tête de votre compte rendu : à remplir une fois ; `raylab report` le relit à chaque exécution.\n"
    "name = \"Votre nom\"\n"
    "group = \"Votre groupe\"\n"
    "course = \"Votre cours\"\n"
    "date = \"\" # vide : le jour de l'exécution (par exemple \"2026-11-23\")\n",
};

#undef NBSP

} // namespace

const Words& wordsFor(const std::string& lang) { return lang == "fr" ? kFrench : kEnglish; }

std::string number(double value, int digits, const Words& words) {
    char text[64];
    if (digits < 0) std::snprintf(text, sizeof text, "%g", value);
    else std::snprintf(text, sizeof text, "%.*f", digits, value);
    std::string out = text;
    if (std::string(words.lang) == "fr")
        for (char& c : out)
            if (c == '.') c = ',';
    return out;
}

std::string seconds(double value, const Words& words) { return number(value, 3, words) + " s"; }

std::string fill(const char* format, std::initializer_list<std::string> args) {
    std::string out;
    auto next = args.begin();
    for (const char* p = format; *p != '\0'; ++p) {
        if (p[0] == '%' && p[1] == 's') {
            if (next == args.end()) throw std::logic_error(std::string("too few arguments for: ") + format);
            out += *next++;
            ++p;
        } else {
            out += *p;
        }
    }
    return out;
}

} // namespace raylab::report
