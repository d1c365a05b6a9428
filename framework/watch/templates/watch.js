// raylab watch's page: asks the state (a long poll: the server answers when something changed),
// shows the pictures, the checks and the compiler's errors, and asks the inspector for a pixel.
// Everything it loads comes from raylab itself, under the address's token.
"use strict";

let state = { version: 0, words: {} };
let zoom = 0;        // screen pixels per picture pixel; 0: each picture a third of the page's width
let flipped = false; // "yours" shows the reference (key F)

const $ = (id) => document.getElementById(id);
const word = (key, values = {}) =>
  (state.words[key] || key).replace(/\{(\w+)\}/g, (all, name) => (name in values ? values[name] : all));

function element(tag, attributes = {}, text = "") {
  const e = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
  if (text) e.textContent = text;
  return e;
}

function cell(row, text, attributes = {}) {
  row.appendChild(element("td", attributes, text));
}

// A picture of the watch's folder; ?v= makes the browser take the new one after each grade.
function picture(path) {
  return "files/" + path + "?v=" + state.version;
}

function showHeader() {
  document.documentElement.lang = state.language || "en";
  document.title = word("title", { lab: state.lab });
  $("title").textContent = word("title", { lab: state.lab });
  $("phase").textContent = word(state.phase);
  $("phase").className = "phase " + (state.phase === "build_failed" ? "fail" : state.phase === "ready" ? "pass" : "");
  $("changed").textContent = state.changed && state.changed.length ? word("changed", { files: state.changed.join(", ") }) : "";
  const seconds = state.seconds || {};
  $("seconds").textContent = word("seconds", { build: (seconds.build || 0).toFixed(1), grade: (seconds.grade || 0).toFixed(1) });
  $("keys").textContent = word("keys");
  $("checks-title").textContent = word("checks");
  $("inspector-title").textContent = word("inspector");
  if (!$("inspector-where").textContent) $("inspector-where").textContent = word("inspector_hint");
}

function showBuild() {
  const build = state.build || { errors: [], output: "" };
  const failed = state.phase === "build_failed";
  $("build").hidden = !failed;
  $("build-title").textContent = word("compile_errors");
  const list = $("build-errors");
  list.replaceChildren();
  for (const e of build.errors) {
    const item = element("li");
    item.appendChild(element("code", { class: "where" }, e.file + ":" + e.line + (e.column ? ":" + e.column : "")));
    item.appendChild(document.createTextNode(" " + e.message));
    list.appendChild(item);
  }
  $("build-output").textContent = failed && build.errors.length === 0 ? build.output : "";
}

function showProblems() {
  const problems = state.problems || [];
  const box = $("problems");
  box.hidden = problems.length === 0;
  box.replaceChildren(element("h2", {}, word("problems")));
  for (const p of problems) box.appendChild(element("pre", { class: "fail" }, p));
}

// One picture: yours, the reference or the difference; a click asks the inspector for its pixel.
function figurePicture(f, kind, path, caption) {
  const figure = element("figure");
  if (path) {
    const img = element("img", { src: picture(path), alt: f.id + " " + kind, "data-kind": kind, "data-figure": f.id });
    if (zoom > 0) img.style.width = f.width * zoom + "px";
    img.addEventListener("click", (event) => {
      const box = img.getBoundingClientRect(); // its border around the picture's own pixels
      const x = Math.floor((event.clientX - box.left - img.clientLeft) / img.clientWidth * f.width);
      const y = Math.floor((event.clientY - box.top - img.clientTop) / img.clientHeight * f.height);
      inspect(f.id, x, y);
    });
    figure.appendChild(img);
  } else {
    figure.appendChild(element("p", {}, word("no_image")));
  }
  figure.appendChild(element("figcaption", { class: kind + "-caption" }, caption));
  return figure;
}

function showFigures() {
  const main = $("figures");
  main.replaceChildren();
  main.className = (flipped ? "flipped" : "") + (zoom > 0 ? " zoomed" : "");
  for (const f of state.figures || []) {
    const block = element("section", { class: "figure", id: "figure-" + f.id });
    const verdict = element("b", { class: f.passed ? "pass" : "fail" }, word(f.passed ? "pass" : "fail"));
    const heading = element("h2", {}, f.id + " ");
    heading.appendChild(verdict);
    block.appendChild(heading);
    const pictures = element("div", { class: "pictures" });
    const mine = flipped ? f.reference : f.student;
    pictures.appendChild(figurePicture(f, "yours", mine, flipped ? word("reference") + " (F)" : word("yours")));
    pictures.appendChild(figurePicture(f, "reference", f.reference, word("reference")));
    pictures.appendChild(figurePicture(f, "difference", f.difference, word("difference", { scale: f.scale })));
    block.appendChild(pictures);
    block.appendChild(element("pre", { class: "reason" }, f.reason + (f.diagnosis ? "\n" + f.diagnosis : "")));
    main.appendChild(block);
  }
}

function showChecks() {
  const table = $("checks");
  table.replaceChildren();
  for (const c of state.checks || []) {
    const row = element("tr", { class: c.passed ? "passed" : "failed" });
    cell(row, word(c.passed ? "pass" : "fail"), { class: c.passed ? "pass" : "fail" });
    cell(row, c.name);
    const message = element("td");
    message.appendChild(element("pre", {}, c.message));
    row.appendChild(message);
    table.appendChild(row);
  }
}

function show() {
  showHeader();
  showBuild();
  showProblems();
  showFigures();
  showChecks();
  document.body.dataset.version = state.version;
  document.body.dataset.phase = state.phase;
}

function value(v) {
  if (v === null || v === undefined) return "-";
  if (Array.isArray(v)) return v.map(value).join("\n");
  if (typeof v === "number") return Number(v.toPrecision(6)).toString();
  return String(v);
}

async function inspect(figure, x, y) {
  $("inspector-where").textContent = word("pixel", { figure, x, y });
  $("inspector").dataset.state = "asking";
  const response = await fetch("inspect?figure=" + encodeURIComponent(figure) + "&x=" + x + "&y=" + y);
  const answer = await response.json();
  $("inspector-note").textContent = answer.note || "";
  const table = $("inspector-rows");
  table.replaceChildren();
  const head = element("tr");
  for (const key of ["quantity", "your_value", "reference_value"]) head.appendChild(element("th", {}, word(key)));
  table.appendChild(head);
  // Each quantity: its name, the function that computes it, the handout's formula and section; the
  // two values beside them.
  answer.rows.forEach((r, k) => {
    const row = element("tr", { class: (r.differs ? "differs" : "") + (k === answer.first ? " first" : ""), "data-name": r.name });
    if (k === answer.first) row.title = word("first_difference");
    const what = element("td");
    what.appendChild(element("div", { class: "name" }, r.name));
    what.appendChild(element("div", { class: "function" }, word("function") + " " + (r.function || word("framework"))));
    what.appendChild(element("div", { class: "formula" }, r.formula));
    what.appendChild(element("div", { class: "handout" }, word("handout", { section: r.handout })));
    row.appendChild(what);
    cell(row, value(r.student), { class: "student" });
    cell(row, value(r.reference), { class: "reference" });
    table.appendChild(row);
  });
  $("inspector").dataset.state = "answered";
  $("inspector").dataset.first = answer.first;
}

document.addEventListener("keydown", (event) => {
  if (event.target.tagName === "INPUT") return;
  if (event.key === "f" || event.key === "F") flipped = !flipped;
  else if (event.key === "+" || event.key === "=") zoom = zoom === 0 ? 1 : Math.min(zoom * 2, 32);
  else if (event.key === "-") zoom = zoom <= 1 ? 0 : zoom / 2;
  else return;
  showFigures();
});

// The long poll: each answer is the newest state; an error (raylab watch stopped) is said, and the
// page tries again.
async function follow() {
  for (;;) {
    try {
      const response = await fetch("state?since=" + state.version);
      const next = await response.json();
      $("lost").hidden = true;
      if (next.version !== state.version) {
        state = next;
        show();
      }
    } catch (error) {
      $("lost").textContent = word("lost");
      $("lost").hidden = false;
      await new Promise((resolve) => setTimeout(resolve, 1000));
    }
  }
}

follow();
