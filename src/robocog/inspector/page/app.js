// robocog inspector: draws the snapshots the server streams, sends the console's commands.
// Plain DOM, no library: everything the page needs is in this file.
"use strict";

const SVGNS = "http://www.w3.org/2000/svg";
const token = new URLSearchParams(location.search).get("token");
const q = (path) => path + (token ? (path.includes("?") ? "&" : "?") + "token=" + encodeURIComponent(token) : "");
const $ = (id) => document.getElementById(id);

function h(tag, attrs, ...kids) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v === null || v === undefined || v === false) continue;
    if (k === "class") el.className = v; else if (k === "text") el.textContent = v;
    else if (k.startsWith("on")) el.addEventListener(k.slice(2), v); else el.setAttribute(k, v);
  }
  for (const kid of kids.flat()) if (kid !== null && kid !== undefined) el.append(kid instanceof Node ? kid : String(kid));
  return el;
}
function s(tag, attrs, ...kids) {
  const el = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs || {})) if (v !== null && v !== undefined) el.setAttribute(k, v);
  for (const kid of kids.flat()) if (kid) el.append(kid instanceof Node ? kid : document.createTextNode(String(kid)));
  return el;
}
const fmt = (x, n = 3) => (x === null || x === undefined ? "-" : Number(x).toFixed(n));

const ui = { follow: true, state: null, shown: null, mindKind: null, filter: "", hypPlace: "", consoleSeen: new Map(), lastSeries: 0 };

// ---- network -------------------------------------------------------------------------
async function getJSON(path) {
  const r = await fetch(q(path), { headers: token ? { "X-Robocog-Token": token } : {} });
  if (!r.ok) throw new Error(r.status + " " + (await r.text()));
  return r.json();
}
async function send(kind, text) {
  const headers = { "Content-Type": "application/json" };
  if (token) headers["X-Robocog-Token"] = token;
  const r = await fetch(q("/api/command"), { method: "POST", headers, body: JSON.stringify({ kind, text: text || "" }) });
  const body = await r.json();
  $("console-error").textContent = r.ok ? "" : body.error || "refused";
  if (r.ok) addConsole([body]);
  return body;
}

function connect() {
  const es = new EventSource(q("/api/stream"));
  es.onmessage = (ev) => receive(JSON.parse(ev.data));
  es.onerror = () => { $("loop-state").textContent = "reconnecting"; $("loop-state").className = "badge"; };
}

function receive(data) {
  ui.state = data.state;
  showState(data.state);
  addConsole(data.console || []);
  if (ui.follow && data.snapshot) render(data.snapshot);
  const now = Date.now();
  if (ui.follow && now - ui.lastSeries > 1500) { ui.lastSeries = now; loadSeries(); }
}

function showState(st) {
  const badge = $("loop-state");
  if (!st.live) { badge.textContent = "recorded"; badge.className = "badge recorded"; }
  else if (st.paused) { badge.textContent = "paused"; badge.className = "badge paused"; }
  else { badge.textContent = "running"; badge.className = "badge running"; }
  for (const id of ["pause", "step", "resume", "stop"]) $(id).disabled = !st.live;
  const tl = $("timeline");
  tl.min = st.first; tl.max = Math.max(st.first, st.last);
  if (ui.follow) tl.value = st.last;
  $("run").textContent = st.run || "";
}

// ---- console -------------------------------------------------------------------------
const KINDS = {
  nars: [["tell", "<bottle --> trash>.  or  *volume=100  or  10"], ["ask", "<<({SELF} * {?1}) --> at> =/> <trash --> [see]>>?"]],
  bdi: [["belief", "see(bottle)[source(percept)]"], ["goal", "go_next"], ["query", "at(P)"]],
  planner: [["english", "The BettClamp is on the table."]],
};
function setKinds(kind) {
  if (ui.mindKind === kind) return;
  ui.mindKind = kind;
  const sel = $("console-kind");
  sel.replaceChildren(...(KINDS[kind] || []).map(([k, ph]) => h("option", { value: k, "data-ph": ph, text: k })));
  sel.onchange = () => { $("console-input").placeholder = sel.selectedOptions[0]?.dataset.ph || ""; };
  sel.onchange();
}
function addConsole(entries) {
  const log = $("console-log");
  for (const e of entries) {
    let li = ui.consoleSeen.get(e.id);
    if (!li) { li = h("li", { "data-id": e.id }); ui.consoleSeen.set(e.id, li); log.prepend(li); }
    // the reply to the post may come after the stream has told how the command ended
    else if (li.dataset.status === e.status || e.status === "queued") continue;
    li.dataset.status = e.status;
    li.className = e.status;
    const text = e.kind + (e.text ? " " + e.text : "");
    li.replaceChildren(h("span", { class: "cmd", text: "> " + text }), h("span", { class: "reply", text: e.status === "queued" ? "(waiting for the loop)" : e.reply || "" }));
  }
}
const history = { lines: [], at: 0 };
$("console-form").addEventListener("submit", (ev) => {
  ev.preventDefault();
  const text = $("console-input").value;
  if (!text.trim()) return;
  history.lines.push(text); history.at = history.lines.length;
  // clear the line only if it still holds what was sent: the reply to an earlier post
  // may come after the next line was typed
  send($("console-kind").value, text).then((b) => {
    const input = $("console-input");
    if (!b.error && input.value === text) input.value = "";
  });
});
$("console-input").addEventListener("keydown", (ev) => {  // the lines sent before, as in a shell
  if (ev.key !== "ArrowUp" && ev.key !== "ArrowDown") return;
  ev.preventDefault();
  history.at = Math.max(0, Math.min(history.lines.length, history.at + (ev.key === "ArrowUp" ? -1 : 1)));
  $("console-input").value = history.lines[history.at] || "";
});
// a term clicked in the mind's lists becomes a question in the console
function askAbout(kind, text) {
  const sel = $("console-kind");
  if ([...sel.options].some((o) => o.value === kind)) sel.value = kind;
  $("console-input").value = text;
  $("console-input").focus();
}
$("pause").onclick = () => send("pause");
$("step").onclick = () => send("step");
$("resume").onclick = () => send("resume");
$("stop").onclick = () => send("stop");
$("follow").onchange = (ev) => { ui.follow = ev.target.checked; if (ui.follow) getJSON("/api/snapshot").then(receive); };
$("timeline").oninput = async (ev) => {
  ui.follow = false; $("follow").checked = false;
  const seq = ev.target.value;
  const data = await getJSON("/api/snapshot?seq=" + seq);
  if (data.snapshot) render(data.snapshot);
};
$("filter").oninput = (ev) => { ui.filter = ev.target.value.toLowerCase(); if (ui.shown) renderMind(ui.shown); };
$("chart-place").onchange = (ev) => { ui.hypPlace = ev.target.value; loadSeries(); };

// ---- rendering -----------------------------------------------------------------------
function render(snap) {
  ui.shown = snap;
  $("seq").textContent = snap.seq + " (" + snap.run + ", cycle " + snap.cycle + ")";
  renderWorld(snap.world, snap);
  // the mind's lists are drawn again only when its view is new (it is taken less
  // often than the world's), so a click or a selection in them is not swept away
  const age = snap.seq - snap.mind_seq;
  if (snap.mind_seq !== ui.mindShown || snap.run !== ui.runShown) {
    ui.mindShown = snap.mind_seq; ui.runShown = snap.run;
    renderMind(snap);
  }
  $("mind-caption").textContent = (snap.mind ? snap.mind.kind.toUpperCase() : "") + (age > 0 ? ` (view of ${age} cycles ago)` : "");
}

function renderWorld(w, snap) {
  const svg = $("world");
  const facts = [];
  if (w.kind === "garbage") drawGarbage(svg, w, facts);
  else if (w.kind === "tabletop") drawTabletop(svg, w, facts);
  else if (w.kind === "room") drawRoom(svg, w, facts);
  else drawGeneric(svg, w, facts);
  if (snap.stats && snap.stats.cycle_ms !== undefined) facts.push(["cycle", fmt(snap.stats.cycle_ms, 2) + " ms"]);
  for (const a of snap.actions || []) facts.push(["action", a[0] + " → " + a[1] + (a[2] ? " (" + a[2] + ")" : "")]);
  $("world-facts").replaceChildren(...facts.map(([k, v]) => h("span", {}, h("b", { text: k + ": " }), v)));
  $("world-caption").textContent = w.kind + (w.time !== undefined ? ", t = " + fmt(w.time, 1) + " s" : "");
}

function drawGarbage(svg, w, facts) {
  const S = w.size, Y = (y) => S - y;
  svg.setAttribute("viewBox", `-0.5 -0.5 ${S + 1} ${S + 1}`);
  const g = [];
  g.push(s("rect", { x: 0, y: 0, width: S, height: S, fill: "none", stroke: "#5a6b4f", "stroke-width": 0.15 }));
  for (const c of w.checkpoints) {
    const hot = Math.min(1, (c.hot - 1) / 4);
    g.push(s("circle", { class: "checkpoint", "data-name": c.name, cx: c.x, cy: Y(c.y), r: 1.0,
      fill: `rgba(214,158,46,${0.15 + 0.5 * hot})`, stroke: w.visited.includes(c.name) ? "#2b6cb0" : "#a0aec0", "stroke-width": 0.12 }));
    g.push(s("text", { x: c.x, y: Y(c.y) + 0.35, "font-size": 0.9, "text-anchor": "middle", fill: "#2d3748" }, c.name));
  }
  g.push(s("rect", { x: w.start[0] - 0.4, y: Y(w.start[1]) - 0.4, width: 0.8, height: 0.8, fill: "none", stroke: "#4a5568", "stroke-width": 0.1 }));
  if (w.trajectory && w.trajectory.length > 1)
    g.push(s("polyline", { id: "trajectory", points: w.trajectory.map(([x, y]) => x + "," + Y(y)).join(" "), fill: "none", stroke: "#2b6cb0", "stroke-width": 0.08, "stroke-opacity": 0.7 }));
  for (const o of w.objects) {
    if (o.state === "held") continue;
    const color = o.state === "collected" ? "#a0aec0" : o.upright ? "#2f855a" : "#dd6b20";
    const shape = o.label === "cup" ? s("circle", { cx: o.x, cy: Y(o.y), r: 0.22, fill: color }) : s("rect", { x: o.x - 0.18, y: Y(o.y) - 0.3, width: 0.36, height: 0.6, fill: color, transform: o.upright ? null : `rotate(70 ${o.x} ${Y(o.y)})` });
    shape.setAttribute("class", "object " + o.state);
    shape.setAttribute("data-id", o.id);
    shape.append(s("title", {}, `${o.id} (${o.state}${o.upright ? "" : ", lying over"}), seen ${o.seen}x`));
    if (o.state === "collected") continue;  // collected ones sit in the trailer
    g.push(shape);
  }
  const r = w.robot, deg = (-r.theta * 180) / Math.PI;
  const half = w.fov / 2, R = w.camera_range;
  const wedge = `M0,0 L${R * Math.cos(half)},${-R * Math.sin(half)} A${R},${R} 0 0 1 ${R * Math.cos(half)},${R * Math.sin(half)} Z`;
  const robot = s("g", { id: "robot", "data-x": r.x, "data-y": r.y, transform: `translate(${r.x} ${Y(r.y)}) rotate(${deg})` },
    s("path", { d: wedge, fill: "rgba(43,108,176,0.08)", stroke: "none" }),
    ...(w.detections || []).map((d) => s("line", { class: "detection", x1: 0, y1: 0, x2: d.distance * Math.cos(d.bearing), y2: -d.distance * Math.sin(d.bearing), stroke: "#d53f8c", "stroke-width": 0.07 })),
    s("polygon", { points: "0.6,0 -0.4,0.35 -0.4,-0.35", fill: w.holding ? "#2b6cb0" : "#1a202c" }));
  g.push(robot);
  svg.replaceChildren(...g);
  facts.push(["round", w.round], ["collected", w.collected + " (this round " + w.collected_round + ")"], ["holding", w.holding || "nothing"],
    ["robot", `(${fmt(r.x, 1)}, ${fmt(r.y, 1)})`], ["detections", (w.detections || []).map((d) => d.instance || d.label).join(", ") || "none"]);
  if (w.done) facts.push(["mission", "over"]);
}

function drawRoom(svg, w, facts) {
  const xs = w.walls.flatMap((g) => [g[0], g[2]]), ys = w.walls.flatMap((g) => [g[1], g[3]]);
  const x0 = Math.min(...xs) - 0.3, x1 = Math.max(...xs) + 0.3, y0 = Math.min(...ys) - 0.3, y1 = Math.max(...ys) + 0.3;
  const Y = (y) => y1 - y;
  svg.setAttribute("viewBox", `${x0} ${0} ${x1 - x0} ${y1 - y0}`);
  const line = (g, attrs) => s("line", { x1: g[0], y1: Y(g[1]), x2: g[2], y2: Y(g[3]), ...attrs });
  const g = w.walls.map((seg) => line(seg, { stroke: "#4a5568", "stroke-width": 0.06 }));
  const colors = { door: "#c05621", opposite_door: "#805ad5", doorway: "#2f855a" };
  for (const t of w.targets) g.push(line(t.face, { class: "target", "data-id": t.id, stroke: colors[t.id] || "#d53f8c", "stroke-width": 0.1 }));
  if (w.trajectory.length > 1) g.push(s("polyline", { id: "trajectory", points: w.trajectory.map(([x, y]) => x + "," + Y(y)).join(" "), fill: "none", stroke: "#2b6cb0", "stroke-width": 0.03 }));
  for (const [x, y, m] of w.marks) g.push(s("circle", { cx: x, cy: Y(y), r: 0.04, fill: "#d69e2e" }, s("title", {}, m)));
  const r = w.robot, deg = (-r.theta * 180) / Math.PI;
  g.push(s("g", { id: "robot", "data-x": r.x, "data-y": r.y, transform: `translate(${r.x} ${Y(r.y)}) rotate(${deg})` },
    s("polygon", { points: "0.2,0 -0.13,0.12 -0.13,-0.12", fill: "#1a202c" })));
  svg.replaceChildren(...g);
  facts.push(["phase", w.phase || "-"], ["robot", `(${fmt(r.x, 2)}, ${fmt(r.y, 2)})`], ["left the room", w.exited ? "yes" : "no"]);
  for (const [k, v] of Object.entries(w.seen)) facts.push(["saw " + k, v.source + " " + fmt(v.certainty, 2)]);
}

function drawGeneric(svg, w, facts) {
  facts.push(["body", w.name]);
  for (const p of w.percepts || []) facts.push(["percept", p]);
  if (!w.robot) { svg.setAttribute("viewBox", "0 0 100 20"); svg.replaceChildren(s("text", { x: 2, y: 10, "font-size": 4 }, (w.name || "world") + ": no pose yet")); return; }
  const pts = [...(w.trajectory || []), ...(w.places || []).map((p) => [p.x, p.y]), [w.robot.x, w.robot.y]];
  const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
  const pad = 1.5, x0 = Math.min(...xs) - pad, x1 = Math.max(...xs) + pad, y0 = Math.min(...ys) - pad, y1 = Math.max(...ys) + pad;
  const size = Math.max(x1 - x0, y1 - y0), Y = (y) => y1 - y, k = size / 22;
  svg.setAttribute("viewBox", `${x0} 0 ${size} ${size}`);
  const g = [];
  for (const p of w.places || []) {
    g.push(s("circle", { cx: p.x, cy: Y(p.y), r: 0.6 * k, fill: "rgba(214,158,46,0.3)", stroke: "#a0aec0", "stroke-width": 0.08 * k }));
    g.push(s("text", { x: p.x, y: Y(p.y) + 0.3 * k, "font-size": 0.8 * k, "text-anchor": "middle" }, p.name));
  }
  if ((w.trajectory || []).length > 1) g.push(s("polyline", { id: "trajectory", points: w.trajectory.map(([x, y]) => x + "," + Y(y)).join(" "), fill: "none", stroke: "#2b6cb0", "stroke-width": 0.08 * k }));
  const r = w.robot, deg = (-r.theta * 180) / Math.PI;
  g.push(s("g", { id: "robot", "data-x": r.x, "data-y": r.y, transform: `translate(${r.x} ${Y(r.y)}) rotate(${deg}) scale(${k})` },
    ...(w.detections || []).map((d) => s("line", { class: "detection", x1: 0, y1: 0, x2: (d.distance * Math.cos(d.bearing)) / k, y2: (-d.distance * Math.sin(d.bearing)) / k, stroke: "#d53f8c", "stroke-width": 0.07 })),
    s("polygon", { points: "0.6,0 -0.4,0.35 -0.4,-0.35", fill: "#1a202c" })));
  svg.replaceChildren(...g);
  facts.push(["robot", `(${fmt(r.x, 2)}, ${fmt(r.y, 2)})` + (r.place ? " at " + r.place : "")]);
}

function drawTabletop(svg, w, facts) {
  const fixed = w.fixed, colW = 16, baseY = 70;
  svg.setAttribute("viewBox", `0 0 ${fixed.length * colW + 4} 80`);
  const g = [];
  fixed.forEach((f, i) => {
    const x = 2 + i * colW;
    g.push(s("rect", { class: "fixed", x, y: baseY, width: colW - 2, height: 4, fill: f.endsWith("Bin") ? f.replace("Bin", "").toLowerCase() : "#8b6b4a", stroke: "#333", "stroke-width": 0.2 }));
    g.push(s("text", { x: x + (colW - 2) / 2, y: baseY + 8, "font-size": 2.4, "text-anchor": "middle" }, f));
    const piles = w.stacks[f] || [];
    piles.forEach((pile, k) => {
      const px = x + (k * (colW - 2)) / Math.max(1, piles.length), pw = (colW - 2) / Math.max(1, piles.length);
      pile.forEach((cube, j) => {
        const y = baseY - 7 * (j + 1);
        g.push(s("rect", { class: "cube", "data-name": cube, "data-on": j ? pile[j - 1] : f, x: px + 0.3, y, width: pw - 0.6, height: 6.5, fill: "#f6e05e", stroke: "#744210", "stroke-width": 0.2 }));
        g.push(s("text", { x: px + pw / 2, y: y + 3.8, "font-size": Math.min(2, 24 / Math.max(6, cube.length)), "text-anchor": "middle" }, cube));
      });
    });
  });
  if (w.held) {
    g.push(s("rect", { id: "held", x: 2, y: 2, width: 24, height: 6.5, fill: "#90cdf4", stroke: "#2c5282", "stroke-width": 0.2 }));
    g.push(s("text", { x: 14, y: 6, "font-size": 2, "text-anchor": "middle" }, "hand: " + w.held));
  }
  svg.replaceChildren(...g);
  facts.push(["held", w.held || "nothing"], ["grasps", w.grasps + " (" + w.failed_grasps + " failed)"]);
  for (const l of w.log.slice(-3)) facts.push(["arm", l[1] + " " + l[2]]);
}

// ---- minds ---------------------------------------------------------------------------
const match = (t) => !ui.filter || String(t).toLowerCase().includes(ui.filter);
function table(head, rows, attrs) {
  return h("table", attrs || {}, h("tr", {}, head.map((c) => h("th", { text: c }))), rows);
}
function bar(value, threshold) {
  const b = h("span", { class: "bar" }, h("i", { style: `width:${Math.max(0, Math.min(1, value)) * 100}%` }));
  if (threshold !== undefined) b.append(h("b", { style: `left:${threshold * 100}%` }));
  return b;
}

function renderMind(snap) {
  const m = snap.mind;
  const box = $("mind");
  if (!m) { box.replaceChildren(h("p", { class: "muted", text: "this mind offers no view" })); return; }
  setKinds(m.kind);
  if (m.kind === "nars") box.replaceChildren(...nars(m));
  else if (m.kind === "bdi") box.replaceChildren(...bdi(m));
  else if (m.kind === "planner") box.replaceChildren(...planner(m, snap));
  else box.replaceChildren(h("pre", { class: "error", text: m.error || JSON.stringify(m) }));
}

function nars(m) {
  const out = [];
  const hyp = Object.values(m.hypotheses || {}).sort((a, b) => a.place.localeCompare(b.place));
  out.push(h("h3", { text: "Where trash is seen: <<({SELF} * {p}) --> at> =/> <trash --> [see]>>" }));
  out.push(table(["place", "f", "c", "expectation", ""], hyp.map((r) => h("tr", { "data-place": r.place, title: "click to ask", onclick: () => askAbout("ask", r.term + "?") },
    h("td", { text: r.place }), h("td", { class: "num f", text: fmt(r.f) }), h("td", { class: "num c", text: fmt(r.c) }),
    h("td", { class: "num exp", text: fmt(r.exp) }), h("td", {}, bar(r.exp)))), { id: "hypotheses" }));
  if (!hyp.length) out.push(h("p", { class: "muted", text: "no checkpoint hypothesis yet" }));
  out.push(h("h3", { text: `Decisions (desire against the threshold ${fmt(m.threshold)})` }));
  out.push(h("ol", { id: "decisions" }, (m.decisions || []).slice().reverse().slice(0, 12).map((d) => d.executed
    ? h("li", { class: "term", text: `t=${d.time} ${d.executed}` })
    : h("li", {}, bar(d.desire, m.threshold), ` ${fmt(d.desire)} `, h("span", { class: "term", text: d.implication }), h("span", { class: "muted", text: " since " + d.precondition })))));
  out.push(h("h3", { text: `Goals (${(m.goals || []).length})` }));
  out.push(table(["goal", "layer", "priority", "f", "c"], (m.goals || []).filter((g) => match(g.term)).slice(0, 20).map((g) => h("tr", {},
    h("td", { class: "term", text: g.term }), h("td", { class: "num", text: g.layer }), h("td", { class: "num", text: fmt(g.priority) }),
    h("td", { class: "num", text: fmt(g.f) }), h("td", { class: "num", text: fmt(g.c) })))));
  out.push(h("h3", { text: `Concepts by priority (${m.memory.concepts} of ${m.memory.capacity} held)` }));
  out.push(table(["concept", "priority", "belief f", "c", "links"], m.concepts.filter((c) => match(c.term)).map((c) => h("tr", { title: "click to ask", onclick: () => askAbout("ask", c.term + "?") },
    h("td", { class: "term", text: c.term }), h("td", { class: "num", text: fmt(c.priority, 4) }),
    h("td", { class: "num", text: c.belief ? fmt(c.belief.f) : "-" }), h("td", { class: "num", text: c.belief ? fmt(c.belief.c) : "-" }),
    h("td", { class: "num", text: c.links }))), { id: "concepts" }));
  out.push(h("h3", { text: "Implication tables" }));
  for (const t of m.tables || []) {
    const rows = t.rows.filter((r) => match(r.term));
    if (!rows.length) continue;
    out.push(h("div", { class: "muted term", text: "=/> " + t.consequent }));
    out.push(table(["implication", "op", "f", "c", "exp"], rows.map((r) => h("tr", {}, h("td", { class: "term", text: r.term }),
      h("td", { text: r.op || "" }), h("td", { class: "num", text: fmt(r.f) }), h("td", { class: "num", text: fmt(r.c) }), h("td", { class: "num", text: fmt(r.exp) })))));
  }
  out.push(h("h3", { text: "Anticipations" }));
  out.push(table(["predicted", "at", "f", "c"], (m.anticipations || []).slice(0, 15).map((a) => h("tr", {},
    h("td", { class: "term", text: a.term }), h("td", { class: "num", text: a.time }), h("td", { class: "num", text: fmt(a.f) }), h("td", { class: "num", text: fmt(a.c) })))));
  if (m.executed) { out.push(h("h3", { text: "Operations executed" })); out.push(h("div", { class: "term", text: m.executed.slice(-12).join(" · ") })); }
  return out;
}

function bdi(m) {
  const out = [];
  out.push(h("h3", { text: `Intentions (${m.intentions.length})` }));
  const ints = h("div", { id: "intentions" });
  for (const i of m.intentions) {
    ints.append(h("div", { class: "intention", "data-id": i.id }, h("div", { class: "muted", text: `intention ${i.id}: ${i.state}` }),
      i.stack.map((f, k) => h("div", { class: "frame" + (k === 0 ? " top" : "") }, h("span", { class: "term", text: f.trigger }),
        f.plan ? h("span", { class: "muted", text: "  @" + f.plan }) : null,
        f.next.length ? h("div", { class: "term muted", text: "next: " + f.next.join("; ") }) : null))));
  }
  if (!m.intentions.length) ints.append(h("p", { class: "muted", text: "no intention" }));
  out.push(ints);
  out.push(h("h3", { text: `Events (${m.events.length})` }));
  out.push(h("ol", { id: "events", class: "term" }, m.events.slice(0, 20).map((e) => h("li", { text: e }))));
  const beliefs = m.beliefs.filter(match);
  out.push(h("h3", { text: `Belief base (${m.beliefs.length})` }));
  out.push(h("ul", { id: "beliefs", class: "term" }, beliefs.slice(0, 150).map((b) => h("li", { text: b, title: "click to query", onclick: () => askAbout("query", b.replace(/\[.*\]$/, "")) }))));
  if (m.actions) { out.push(h("h3", { text: "Actions" })); out.push(h("div", { class: "term", text: m.actions.slice(-12).join(" · ") })); }
  if (m.output && m.output.length) { out.push(h("h3", { text: "Output" })); out.push(h("pre", { class: "term", text: m.output.slice(-10).join("\n") })); }
  return out;
}

function planner(m, snap) {
  const out = [];
  const r = m.request;
  out.push(h("h3", { text: "Request" }));
  if (!r) out.push(h("p", { class: "muted", text: "no request yet: give one in English below" }));
  else {
    out.push(h("div", { id: "planner-request" }, h("span", { class: "term", text: r.text }), " ",
      h("span", { id: "planner-status", class: "pill", text: r.status }), r.message ? h("span", { class: "error", text: " " + r.message }) : null));
    out.push(h("div", {}, "goal: ", r.goal.map((f) => h("span", { class: "pill term", text: f.join(" ") }))));
    out.push(h("div", { class: "muted", text: `plans searched: ${r.plans.length}, replans: ${r.replans}` + (r.plans.length ? `, last: ${r.plans[r.plans.length - 1].iterations} iterations in ${fmt(r.plans[r.plans.length - 1].seconds * 1000, 1)} ms` : "") }));
    if (r.failures.length) out.push(h("div", { class: "error", text: "failed steps: " + r.failures.join("; ") }));
  }
  out.push(h("h3", { text: "Plan" }));
  out.push(h("ol", { id: "planner-plan", class: "term" }, m.plan.map((st, i) => h("li", { class: i < m.step ? "step-done" : i === m.step && r && r.status === "executing" ? "step-now" : "", text: st }))));
  out.push(h("h3", { text: "State atoms (the scene the planner tracks)" }));
  if (m.scene) out.push(h("div", { class: "term" }, Object.entries(m.scene.on).map(([a, b]) => h("span", { class: "pill", text: `${a} on ${b}` })), m.scene.held ? h("span", { class: "pill", text: "holding " + m.scene.held }) : null));
  out.push(atomBrowser(snap));
  if (m.history.length > 1) { out.push(h("h3", { text: "Earlier requests" })); out.push(h("ul", {}, m.history.map((x) => h("li", { text: `${x.status}: ${x.text}` })))); }
  return out;
}

const atomState = { type: "", name: "", key: "" };
function atomBrowser(snap) {
  const box = h("div", { id: "atoms" });
  const typeSel = h("select", { id: "atom-type" }, ["", "ConceptNode", "PredicateNode", "EvaluationLink", "InheritanceLink", "ListLink"].map((t) => h("option", { value: t, text: t || "any type" })));
  typeSel.value = atomState.type;
  typeSel.onchange = () => { atomState.type = typeSel.value; };
  const name = h("input", { id: "atom-name", placeholder: "name contains", value: atomState.name, maxlength: 200 });
  name.oninput = () => { atomState.name = name.value; };
  const results = h("div", { id: "atom-results" });
  const search = async () => {
    atomState.type = typeSel.value; atomState.name = name.value; atomState.key = "";
    const d = await getJSON(`/api/atoms?seq=${snap.seq}&type=${encodeURIComponent(typeSel.value)}&name=${encodeURIComponent(name.value)}`);
    results.replaceChildren(...d.atoms.slice(0, 40).map((a) => atomLine(a, snap, results)));
  };
  box.append(h("h3", { text: "AtomSpace" }), h("div", {}, typeSel, " ", name, " ", h("button", { id: "atom-search", type: "button", onclick: search, text: "Find" })), results);
  if (atomState.key) showAtom(atomState.key, snap, results); else if (atomState.name || atomState.type) search();
  return box;
}
function atomLine(a, snap, results) {
  return h("div", {}, h("span", { class: "atom-link term", text: a.key, onclick: () => showAtom(a.key, snap, results) }),
    h("span", { class: "muted", text: ` ${a.in_goal ? "goal " : ""}${a.in_state ? "state" : ""} · ${a.incoming.length} incoming` }));
}
async function showAtom(key, snap, results) {
  atomState.key = key;
  const d = await getJSON(`/api/atoms?seq=${snap.seq}&key=${encodeURIComponent(key)}`);
  const a = d.atom;
  if (!a) { results.replaceChildren(h("p", { class: "muted", text: "not in this state" })); return; }
  const link = (k) => h("div", {}, h("span", { class: "atom-link term", text: k, onclick: () => showAtom(k, snap, results) }));
  results.replaceChildren(h("div", { class: "term", id: "atom-shown", text: a.key }),
    h("div", { class: "muted", text: "outgoing" }), ...a.outgoing.map(link),
    h("div", { class: "muted", text: "incoming" }), ...a.incoming.map(link));
}

// ---- charts --------------------------------------------------------------------------
function lineChart(svg, lines, opts) {
  const W = 320, H = 110, L = 30, B = 14, T = 6, R = 6;
  const pts = lines.flatMap((l) => l.points);
  if (!pts.length) { svg.replaceChildren(s("text", { x: L, y: H / 2 }, "no data yet")); return; }
  const xs = pts.map((p) => p[0]), ys = pts.map((p) => p[1]);
  const x0 = Math.min(...xs), x1 = Math.max(...xs, x0 + 1);
  const y0 = opts.y0 !== undefined ? opts.y0 : Math.min(...ys), y1 = opts.y1 !== undefined ? opts.y1 : Math.max(...ys, y0 + 1e-9);
  const X = (x) => L + ((x - x0) / (x1 - x0)) * (W - L - R), Yc = (y) => H - B - ((y - y0) / (y1 - y0 || 1)) * (H - B - T);
  const g = [s("line", { x1: L, y1: H - B, x2: W - R, y2: H - B, stroke: "#cbd5e0" }), s("line", { x1: L, y1: T, x2: L, y2: H - B, stroke: "#cbd5e0" }),
    s("text", { x: 2, y: T + 6 }, fmt(y1, opts.digits ?? 1)), s("text", { x: 2, y: H - B }, fmt(y0, opts.digits ?? 1)),
    s("text", { x: L, y: H - 2 }, "cycle " + x0), s("text", { x: W - R - 50, y: H - 2 }, "cycle " + x1)];
  for (const m of opts.marks || []) if (m[0] >= x0) g.push(s("line", { x1: X(m[0]), x2: X(m[0]), y1: T, y2: H - B, stroke: "#cbd5e0", "stroke-dasharray": "2 2" }));
  for (const m of opts.labels || []) if (m[0] >= x0) g.push(s("text", { x: X(m[0]) + 2, y: T + 8 }, "round " + m[1]));
  lines.forEach((l) => { if (l.points.length) g.push(s("polyline", { class: "series", "data-name": l.name, points: l.points.map((p) => X(p[0]) + "," + Yc(p[1])).join(" "), fill: "none", stroke: l.color, "stroke-width": 1.4 })); });
  svg.replaceChildren(...g);
}
async function loadSeries() {
  let d;
  try { d = await getJSON("/api/series"); } catch (e) { return; }
  $("chart-collected").parentElement.hidden = !d.collected.length;
  $("chart-hyp").parentElement.hidden = !Object.keys(d.hypotheses).length;
  lineChart($("chart-collected"), [{ name: "collected", points: d.collected, color: "#2f855a" }], { y0: 0, digits: 0, marks: d.runs });
  lineChart($("chart-cycle"), [{ name: "cycle", points: d.cycle_ms, color: "#2b6cb0" }], { y0: 0, digits: 2, marks: d.runs });
  const places = Object.keys(d.hypotheses).sort();
  const sel = $("chart-place");
  if (sel.options.length !== places.length + 1) {
    sel.replaceChildren(h("option", { value: "", text: "all" }), ...places.map((p) => h("option", { value: p, text: p })));
    sel.value = ui.hypPlace;
  }
  const colors = ["#2b6cb0", "#c53030", "#2f855a", "#b7791f", "#6b46c1", "#d53f8c", "#319795", "#4a5568"];
  const chosen = places.filter((p) => !ui.hypPlace || p === ui.hypPlace);
  lineChart($("chart-hyp"), chosen.map((p) => ({ name: p, points: d.hypotheses[p], color: colors[places.indexOf(p) % colors.length] })), { y0: 0, y1: 1, digits: 1, marks: d.runs.concat(d.rounds), labels: d.rounds });
}

setInterval(() => { if (ui.follow) loadSeries(); }, 2000);
getJSON("/api/snapshot").then((d) => { receive(d); connect(); loadSeries(); }).catch((e) => { $("loop-state").textContent = "error: " + e.message; });
