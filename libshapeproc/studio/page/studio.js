// The studio's page: a thin view over the server's session. Every edit is one POST; pictures come
// from a long poll of /api/preview; the state (model, edits, seed) from /api/state.
"use strict";
const token = new URLSearchParams(location.search).get("token") || "";
const $ = (id) => document.getElementById(id);
const SVG = "http://www.w3.org/2000/svg";
let state = null;
const chosenAxis = {};   // pair index -> axis index shown
const everyAxis = {};    // pair index -> edits apply to every axis

async function call(path, body) {
  const options = { headers: { "X-Studio-Token": token } };
  if (body !== undefined) {
    options.method = "POST";
    options.headers["Content-Type"] = "application/json";
    options.body = JSON.stringify(body);
  }
  const response = await fetch(path, options);
  if (response.status === 204) return null;
  const json = await response.json();
  if (!response.ok) throw new Error(json.error || response.statusText);
  return json;
}

function showError(message) {
  const e = $("error");
  e.textContent = message || "";
  e.hidden = !message;
}

async function act(path, body) {
  try {
    showError("");
    const next = await call(path, body === undefined ? {} : body);
    if (next && next.phase) render(next);
    return next;
  } catch (error) {
    showError(error.message);
    return null;
  }
}

function edit(request) { return act("/api/edit", request); }

// ---- the interaction functions -------------------------------------------------------------
const plot = { width: 480, height: 190, left: 44, right: 12, top: 10, bottom: 26, span: 2 };
const yOf = (gamma) => {
  const v = gamma <= 0 ? -plot.span : Math.max(-plot.span, Math.min(plot.span, Math.log10(gamma)));
  const mid = plot.top + (plot.height - plot.top - plot.bottom) / 2;
  return mid - v * (plot.height - plot.top - plot.bottom) / (2 * plot.span);
};
const gammaOf = (y) => {
  const mid = plot.top + (plot.height - plot.top - plot.bottom) / 2;
  const v = (mid - y) * (2 * plot.span) / (plot.height - plot.top - plot.bottom);
  if (v <= -plot.span + 0.02) return 0;
  return Math.pow(10, Math.min(plot.span, v));
};

function element(name, attributes, parent) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

function round(x) { return Number(x.toPrecision(4)); }

// A draggable handle: `move(dx, dy)` while dragging, `done(dx, dy)` on release; keys as given.
function draggable(handle, move, done, keys) {
  let start = null;
  handle.addEventListener("pointerdown", (event) => {
    start = [event.clientX, event.clientY];
    handle.setPointerCapture(event.pointerId);
    event.preventDefault();
  });
  handle.addEventListener("pointermove", (event) => {
    if (start) move(event.clientX - start[0], event.clientY - start[1]);
  });
  handle.addEventListener("pointerup", (event) => {
    if (!start) return;
    const d = [event.clientX - start[0], event.clientY - start[1]];
    start = null;
    if (d[0] !== 0 || d[1] !== 0) done(d[0], d[1]);
  });
  handle.addEventListener("keydown", (event) => {
    if (keys[event.key]) { keys[event.key](); event.preventDefault(); }
  });
}

function drawPair(p, pair, model) {
  const box = document.createElement("div");
  box.className = "pair";
  const names = model.categories.map((c) => c.name);
  const title = document.createElement("h3");
  title.textContent = `Pair ${p}: ${names[pair.first]} – ${names[pair.second]}`;
  title.style.fontSize = "0.9rem";
  box.appendChild(title);
  const a = Math.min(chosenAxis[p] || 0, pair.axes.length - 1);
  const controls = document.createElement("div");
  controls.className = "axis-controls";
  if (pair.axes.length > 1) {
    const label = document.createElement("label");
    label.textContent = "Axis ";
    const select = document.createElement("select");
    pair.axes.forEach((axis, k) => {
      const angle = Math.round(Math.atan2(axis.direction[1], axis.direction[0]) * 180 / Math.PI);
      select.add(new Option(`${k} (${angle}°)`, k, false, k === a));
    });
    select.addEventListener("change", () => { chosenAxis[p] = Number(select.value); render(state); });
    label.appendChild(select);
    controls.appendChild(label);
    const all = document.createElement("label");
    const box2 = document.createElement("input");
    box2.type = "checkbox";
    box2.checked = !!everyAxis[p];
    box2.addEventListener("change", () => { everyAxis[p] = box2.checked; });
    all.append(box2, " edit every axis");
    controls.appendChild(all);
  }
  box.appendChild(controls);
  const axis = pair.axes[a];
  const xMax = Math.max(...pair.axes.map((x) => x.thresholds[x.thresholds.length - 1])) * 1.15 || 1;
  const xOf = (d) => plot.left + d / xMax * (plot.width - plot.left - plot.right);
  const dOf = (x) => (x - plot.left) / (plot.width - plot.left - plot.right) * xMax;
  const svg = element("svg", { viewBox: `0 0 ${plot.width} ${plot.height}`, role: "group",
    "aria-label": `interaction of pair ${p}, axis ${a}` });
  const bottom = plot.height - plot.bottom;
  element("rect", { class: "core", x: xOf(0), y: plot.top, width: xOf(axis.thresholds[0]) - xOf(0),
    height: bottom - plot.top }, svg);
  const where = { pair: p, axis: a, every_axis: !!everyAxis[p] };
  axis.gammas.forEach((gamma, k) => {
    const x0 = xOf(axis.thresholds[k]), x1 = xOf(axis.thresholds[k + 1]);
    const y = yOf(gamma), y1 = yOf(1);
    const bar = element("rect", { class: gamma >= 1 ? "bar-up" : "bar-down", x: x0 + 1,
      y: Math.min(y, y1), width: Math.max(1, x1 - x0 - 2), height: Math.abs(y1 - y) }, svg);
    element("title", {}, bar).textContent = `band ${k + 1}: γ = ${round(gamma)} (${axis.status[k]})`;
    const handle = element("rect", { class: "handle", id: `gamma-${p}-${a}-${k}`, x: x0 + 2,
      y: y - 5, width: Math.max(6, x1 - x0 - 4), height: 10, rx: 3, tabindex: 0, role: "slider",
      "aria-label": `pair ${p} axis ${a} band ${k + 1} gamma`, "aria-valuenow": round(gamma) }, svg);
    const scale = () => svg.getBoundingClientRect().height / plot.height || 1;
    const send = (value) => edit({ kind: "gamma", ...where, index: k, value: round(value) });
    draggable(handle, (dx, dy) => {
      const yy = y + dy / scale();
      handle.setAttribute("y", yy - 5);
      bar.setAttribute("y", Math.min(yy, y1));
      bar.setAttribute("height", Math.abs(y1 - yy));
    }, (dx, dy) => send(gammaOf(y + dy / scale())), {
      ArrowUp: () => send(Math.max(gamma, 0.01) * 1.25),
      ArrowDown: () => send(gamma * 0.8),
    });
  });
  element("line", { class: "unit-line", x1: plot.left, x2: plot.width - plot.right, y1: yOf(1),
    y2: yOf(1) }, svg);
  axis.thresholds.forEach((t, i) => {
    const x = xOf(t);
    const line = element("line", { class: "threshold", x1: x, x2: x, y1: plot.top, y2: bottom }, svg);
    const grip = element("rect", { class: "threshold-grip handle", id: `threshold-${p}-${a}-${i}`,
      x: x - 5, y: plot.top, width: 10, height: bottom - plot.top, tabindex: 0, role: "slider",
      "aria-label": `pair ${p} axis ${a} threshold ${i}`, "aria-valuenow": round(t) }, svg);
    element("title", {}, grip).textContent = `δ${i} = ${round(t)} ${state.model.units}`;
    element("text", { class: "tick", x, y: bottom + 11, "text-anchor": "middle" }, svg)
      .textContent = i === 0 || i === axis.thresholds.length - 1 ? String(round(t)) : "";
    const scale = () => svg.getBoundingClientRect().width / plot.width || 1;
    const send = (value) => edit({ kind: "threshold", ...where, index: i, value: round(value) });
    draggable(grip, (dx) => {
      line.setAttribute("x1", x + dx / scale());
      line.setAttribute("x2", x + dx / scale());
    }, (dx) => send(Math.max(0, dOf(x + dx / scale()))), {
      ArrowRight: () => send(t + xMax * 0.01),
      ArrowLeft: () => send(Math.max(0, t - xMax * 0.01)),
    });
  });
  for (const g of [0.01, 0.1, 1, 10, 100]) {
    element("text", { x: plot.left - 4, y: yOf(g) + 4, "text-anchor": "end", "font-size": 10 }, svg)
      .textContent = `γ ${g}`;
  }
  element("text", { class: "tick", x: plot.width - plot.right, y: plot.height - 2,
    "text-anchor": "end" }, svg).textContent = `distance (${state.model.units})`;
  box.appendChild(svg);
  return box;
}

// ---- sliders ---------------------------------------------------------------------------------
// A logarithmic slider over [value / 10, value * 10] of the value the fit gave.
function slider(label, value, fitted, onChange) {
  const row = document.createElement("div");
  row.className = "slider";
  const name = document.createElement("label");
  name.textContent = label;
  const input = document.createElement("input");
  input.type = "range"; input.min = -1; input.max = 1; input.step = 0.01;
  input.value = Math.log10(value / fitted);
  input.setAttribute("aria-label", label);
  const shown = document.createElement("output");
  shown.textContent = round(value);
  input.addEventListener("input", () => { shown.textContent = round(fitted * Math.pow(10, input.value)); });
  input.addEventListener("change", () => onChange(round(fitted * Math.pow(10, input.value))));
  name.htmlFor = input.id = `slider-${label.replace(/\W+/g, "-")}`;
  row.append(name, input, shown);
  return row;
}

let fitted = null;  // the first model the page saw: the sliders' centres

function renderModel(model) {
  if (!fitted) fitted = model;
  const betas = $("betas");
  betas.replaceChildren(...model.categories.map((c, k) =>
    slider(`β ${c.name}`, c.beta, fitted.categories[k] ? fitted.categories[k].beta : c.beta,
      (v) => edit({ kind: "beta", index: k, value: v }))));
  $("classes-block").hidden = model.classes.length === 0;
  $("classes").replaceChildren(...model.classes.map((c, k) =>
    slider(`class ${k} ${c.label || ""} (${model.categories[c.category].name})`, c.weight,
      fitted.classes[k] ? fitted.classes[k].weight : c.weight,
      (v) => edit({ kind: "class", index: k, value: v }))));
  $("pairs").replaceChildren(...model.pairs.map((pair, p) => drawPair(p, pair, model)));
}

function render(next) {
  state = next;
  const fitting = next.phase === "fitting";
  $("fitting").hidden = !fitting;
  $("toolbar").hidden = next.phase !== "ready";
  $("exemplar-figure").hidden = !next.has_exemplar;
  if (fitting) {
    $("fit-stage").textContent = `${next.fit.stage || "starting"} ${next.fit.total ?
      `${next.fit.done} of ${next.fit.total}` : ""} (${next.fit.seconds.toFixed(1)} s)`;
    const bar = $("fit-progress");
    if (next.fit.total) { bar.max = next.fit.total; bar.value = next.fit.done; }
    else bar.removeAttribute("value");
    $("status").textContent = "fitting the exemplar…";
    return;
  }
  if (next.phase === "failed") {
    showError(`the fit failed: ${next.error}`);
    return;
  }
  $("undo").disabled = !next.can_undo;
  $("redo").disabled = !next.can_redo;
  if (document.activeElement !== $("seed")) $("seed").value = next.seed;
  document.querySelector(`input[name=size][value=${next.full ? "full" : "preview"}]`).checked = true;
  $("edits").replaceChildren(...next.edits.map((e) => {
    const li = document.createElement("li"); li.textContent = e; return li;
  }));
  if (next.model) {
    const focused = document.activeElement && document.activeElement.id;
    renderModel(next.model);
    if (focused && $(focused)) $(focused).focus();
  }
}

// ---- previews --------------------------------------------------------------------------------
function showPreview(p) {
  const box = $("preview");
  if (p.svg) box.innerHTML = p.svg;
  box.dataset.sequence = p.sequence;
  box.dataset.stage = p.stage;
  box.dataset.revision = p.revision;
  $("preview-caption").textContent = p.stage === "draft"
    ? `(draft: ${p.elements} elements, ${(p.seconds * 1000).toFixed(0)} ms; sampling the output…)`
    : p.stage === "cut" ? `(draft: ${p.elements} elements; ${p.note})`
    : `(${p.elements} elements, seed ${p.seed}, ${p.size.map(round).join(" × ")}, ` +
      `${p.steps} steps, ${p.seconds.toFixed(2)} s${p.stationary ? "" : ", not stationary"})`;
  const table = $("verdicts");
  if (p.stage !== "final") {
    table.classList.add("stale");
    if (p.stage === "cut") $("summary").textContent = p.note;
    return;
  }
  table.classList.remove("stale");
  table.dataset.sequence = p.sequence;
  $("summary").textContent = p.note || p.summary ||
    (state && state.has_exemplar ? "" : "No exemplar: open one to see verdicts.");
  table.tBodies[0].replaceChildren(...p.verdicts.map((v) => {
    const tr = document.createElement("tr");
    tr.className = v.outcome;
    for (const text of [v.metric, v.shown, v.rule, v.outcome + (v.problem ? `: ${v.problem}` : "")]) {
      const td = document.createElement("td"); td.textContent = text; tr.appendChild(td);
    }
    tr.lastChild.className = "outcome";
    return tr;
  }));
  $("status").textContent = `preview of revision ${p.revision} ready`;
}

async function pollPreviews() {
  let after = 0;
  for (;;) {
    try {
      const p = await call(`/api/preview?after=${after}`);
      if (p) { after = p.sequence; showPreview(p); }
    } catch (error) {
      showError(`lost the studio: ${error.message}`);
      await new Promise((r) => setTimeout(r, 2000));
    }
  }
}

async function pollState() {
  for (;;) {
    try {
      const next = await call("/api/state");
      render(next);
      if (next.phase !== "fitting") return;
    } catch (error) {
      showError(error.message);
    }
    await new Promise((r) => setTimeout(r, 400));
  }
}

async function load() {
  try {
    const response = await fetch("/api/exemplar.svg", { headers: { "X-Studio-Token": token } });
    const text = await response.text();
    if (text) $("exemplar").innerHTML = text;
  } catch (error) { showError(error.message); }
  $("undo").onclick = () => act("/api/undo");
  $("redo").onclick = () => act("/api/redo");
  $("reset").onclick = () => act("/api/reset");
  $("isotropic").onclick = () => edit({ kind: "isotropic" });
  $("scale-apply").onclick = () => edit({ kind: "scale-thresholds", value: Number($("scale").value) });
  $("reroll").onclick = () => act("/api/seed", { reroll: true });
  $("seed").addEventListener("change", () => act("/api/seed", { seed: Number($("seed").value) }));
  for (const radio of document.querySelectorAll("input[name=size]"))
    radio.addEventListener("change", () => act("/api/size", { full: radio.value === "full" }));
  $("export").onclick = async () => {
    $("exported").textContent = "exporting…";
    const done = await act("/api/export", { name: $("export-name").value, overwrite: $("overwrite").checked });
    $("exported").textContent = done ? `wrote ${done.files.join(", ")}; reproduce with: ${done.command}` : "";
  };
  document.addEventListener("keydown", (event) => {
    if (!(event.ctrlKey || event.metaKey) || event.key.toLowerCase() !== "z") return;
    if (event.target.tagName === "INPUT") return;
    act(event.shiftKey ? "/api/redo" : "/api/undo");
    event.preventDefault();
  });
  await pollState();
  pollPreviews();
}

load();
