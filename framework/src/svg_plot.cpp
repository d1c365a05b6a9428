#include "src/svg_plot.h"

#include "src/markup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace raylab {

namespace {

constexpr double kWidth = 760, kHeight = 500;
constexpr double kLeft = 80, kRight = 250, kTop = 40, kBottom = 60; // margins; the legend is on the right
constexpr const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"};

std::string num(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", v);
    return buffer;
}

// A bin edge: "2.5", "10".
std::string formatNumberPlain(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

std::string decade(int e) {
    if (e >= 0 && e <= 4) return std::to_string(int(std::lround(std::pow(10., e))));
    return "1e" + std::to_string(e);
}

// The plot's area: whole decades on both axes, from the positive points of every series.
struct LogFrame {
    int ex0 = 0, ex1 = 1, ey0 = 0, ey1 = 1; // decades: 10^ex0 ... 10^ex1 across, 10^ey0 ... 10^ey1 up
    double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;

    double x(double v) const { return kLeft + (std::log10(v) - ex0) / (ex1 - ex0) * plotW; }
    double y(double v) const { return kTop + (ey1 - std::log10(v)) / (ey1 - ey0) * plotH; }
};

LogFrame frameOf(const LogLogPlot& plot) {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (const Series& s : plot.series)
        for (std::size_t k = 0; k < s.x.size(); ++k)
            if (s.x[k] > 0 && s.y[k] > 0) {
                xmin = std::min(xmin, s.x[k]), xmax = std::max(xmax, s.x[k]);
                ymin = std::min(ymin, s.y[k]), ymax = std::max(ymax, s.y[k]);
            }
    if (!(xmin < INFINITY)) xmin = 1, xmax = 10, ymin = 1, ymax = 10;
    LogFrame f;
    f.ex0 = int(std::floor(std::log10(xmin))), f.ex1 = std::max(f.ex0 + 1, int(std::ceil(std::log10(xmax))));
    f.ey0 = int(std::floor(std::log10(ymin))), f.ey1 = std::max(f.ey0 + 1, int(std::ceil(std::log10(ymax))));
    return f;
}

// Grid and ticks: every decade labelled, the 2..9 in between as light lines.
void writeGrid(std::ostream& svg, const LogFrame& f) {
    for (int e = f.ex0; e <= f.ex1; ++e)
        for (int m = 1; m <= 9 && (e < f.ex1 || m == 1); ++m) {
            const double x = f.x(m * std::pow(10., e));
            svg << "<line x1=\"" << num(x) << "\" y1=\"" << kTop << "\" x2=\"" << num(x) << "\" y2=\"" << kTop + f.plotH
                << "\" stroke=\"" << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
            if (m == 1)
                svg << "<text x=\"" << num(x) << "\" y=\"" << kTop + f.plotH + 18 << "\" text-anchor=\"middle\">" << decade(e) << "</text>\n";
        }
    for (int e = f.ey0; e <= f.ey1; ++e)
        for (int m = 1; m <= 9 && (e < f.ey1 || m == 1); ++m) {
            const double y = f.y(m * std::pow(10., e));
            svg << "<line x1=\"" << kLeft << "\" y1=\"" << num(y) << "\" x2=\"" << kLeft + f.plotW << "\" y2=\"" << num(y)
                << "\" stroke=\"" << (m == 1 ? "#bbb" : "#eee") << "\"/>\n";
            if (m == 1)
                svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\">" << decade(e) << "</text>\n";
        }
}

// The s-th series: its points, the line between them if it has one, and its legend entry.
void writeSeries(std::ostream& svg, const LogFrame& f, const Series& series, std::size_t s) {
    const char* color = kColors[s % std::size(kColors)];
    std::string points;
    for (std::size_t k = 0; k < series.x.size(); ++k) {
        if (!(series.x[k] > 0 && series.y[k] > 0)) continue;
        points += num(f.x(series.x[k])) + "," + num(f.y(series.y[k])) + " ";
        svg << "<circle cx=\"" << num(f.x(series.x[k])) << "\" cy=\"" << num(f.y(series.y[k])) << "\" r=\"3\" fill=\"" << color << "\"/>\n";
    }
    if (series.linesBetween)
        svg << "<polyline points=\"" << points << "\" fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.8\"/>\n";
    const double ly = kTop + 14 + 20 * double(s), lx = kLeft + f.plotW + 15;
    svg << "<line x1=\"" << lx << "\" y1=\"" << ly - 4 << "\" x2=\"" << lx + 22 << "\" y2=\"" << ly - 4 << "\" stroke=\""
        << color << "\" stroke-width=\"" << (series.linesBetween ? 2 : 0) << "\"/><circle cx=\"" << lx + 11 << "\" cy=\""
        << ly - 4 << "\" r=\"3\" fill=\"" << color << "\"/>\n";
    svg << "<text x=\"" << lx + 28 << "\" y=\"" << ly << "\">" << escapeMarkup(series.label) << "</text>\n";
}

// The opening of a plot of `width` by `height`: the white page, the title, the frame of the plotting
// area (plotW by plotH from the margins) and the axes' labels.
void writeFrame(std::ostream& svg, double width, double height, double plotW, double plotH, const std::string& title,
                const std::string& xLabel, const std::string& yLabel) {
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << ' ' << height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<text x=\"" << width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escapeMarkup(title) << "</text>\n";
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << plotW << "\" height=\"" << plotH
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    svg << "<text x=\"" << kLeft + plotW / 2 << "\" y=\"" << height - 15 << "\" text-anchor=\"middle\">" << escapeMarkup(xLabel) << "</text>\n";
    svg << "<text transform=\"translate(18," << kTop + plotH / 2 << ") rotate(-90)\" text-anchor=\"middle\">" << escapeMarkup(yLabel) << "</text>\n";
}

// A histogram's size: smaller than a study's plot, several stand side by side on the class page.
constexpr double kHistogramWidth = 420, kHistogramHeight = 260, kHistogramRight = 20;

} // namespace

std::string toSvg(const LogLogPlot& plot) {
    const LogFrame f = frameOf(plot);
    std::ostringstream svg;
    writeFrame(svg, kWidth, kHeight, f.plotW, f.plotH, plot.title, plot.xLabel, plot.yLabel);
    writeGrid(svg, f);
    for (std::size_t s = 0; s < plot.series.size(); ++s) writeSeries(svg, f, plot.series[s], s);
    svg << "</svg>\n";
    return svg.str();
}

Histogram histogramOf(std::string title, std::string xLabel, std::string yLabel, const std::vector<double>& values,
                      double low, double high, int bins) {
    Histogram h{std::move(title), std::move(xLabel), std::move(yLabel), low, high, std::vector<int>(std::size_t(std::max(bins, 1)), 0)};
    const double width = (high - low) / double(h.counts.size());
    for (double v : values) {
        if (!(v >= low && v <= high)) continue;
        const std::size_t bin = width > 0. ? std::min(h.counts.size() - 1, std::size_t((v - low) / width)) : 0;
        ++h.counts[bin];
    }
    return h;
}

std::string toSvg(const Histogram& h) {
    const double plotW = kHistogramWidth - kLeft - kHistogramRight, plotH = kHistogramHeight - kTop - kBottom;
    std::ostringstream svg;
    writeFrame(svg, kHistogramWidth, kHistogramHeight, plotW, plotH, h.title, h.xLabel, h.yLabel);
    const int highest = std::max(1, h.counts.empty() ? 1 : *std::max_element(h.counts.begin(), h.counts.end()));
    const double barW = plotW / double(std::max<std::size_t>(h.counts.size(), 1));
    for (int tick = 0; tick <= highest; tick += std::max(1, highest / 5)) { // counts up the side
        const double y = kTop + plotH - plotH * tick / highest;
        svg << "<text x=\"" << kLeft - 6 << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\">" << tick << "</text>\n";
    }
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        const double barH = plotH * h.counts[b] / highest, x = kLeft + barW * double(b);
        svg << "<rect x=\"" << num(x + 1) << "\" y=\"" << num(kTop + plotH - barH) << "\" width=\"" << num(barW - 2)
            << "\" height=\"" << num(barH) << "\" fill=\"" << kColors[0] << "\"><title>" << h.counts[b] << "</title></rect>\n";
    }
    for (std::size_t b = 0; b <= h.counts.size(); b += std::max<std::size_t>(1, h.counts.size() / 5)) { // bin edges across
        const double value = h.low + (h.high - h.low) * double(b) / double(std::max<std::size_t>(h.counts.size(), 1));
        svg << "<text x=\"" << num(kLeft + barW * double(b)) << "\" y=\"" << kTop + plotH + 18
            << "\" text-anchor=\"middle\">" << escapeMarkup(formatNumberPlain(value)) << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

} // namespace raylab
