// The oro web inspector: one script for every page, no library.
// Each page asks the server's /api/... for JSON and draws it.
"use strict";

const params = new URLSearchParams(location.search);
const model = params.get("model") || "myself";
const main = document.getElementById("main");

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (k === "class") e.className = v;
    else if (k.startsWith("on")) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v);
  }
  for (const c of children.flat(Infinity)) {
    if (c === null || c === undefined) continue;
    e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  }
  return e;
}

function url(path, extra) {
  const q = new URLSearchParams(Object.assign({model: model}, extra || {}));
  return path + "?" + q.toString();
}

async function api(path, extra) {
  const r = await fetch(url("/api/" + path, extra));
  const data = await r.json();
  if (!r.ok) throw new Error(data.error || r.statusText);
  return data;
}

function showError(e) {
  main.append(el("p", {class: "error"}, String(e.message || e)));
}

// A term: a link to its resource page, or a literal.
function term(t) {
  if (t.iri !== undefined)
    return el("a", {href: url("/resource", {iri: t.iri}), title: t.iri}, t.name);
  const suffix = t.lang ? "@" + t.lang : "";
  return el("span", {class: "lit", title: t.datatype || ""}, '"' + t.literal + '"' + suffix);
}

function table(headers, rows, rowClass) {
  return el("table", {},
    el("tr", {}, headers.map(h => el("th", {}, h))),
    rows.map(r => el("tr", {class: rowClass || ""},
      r.map(c => el("td", typeof c === "number" ? {class: "num"} : {}, c)))));
}

// ---- overview -------------------------------------------------------

async function overview() {
  const o = await api("overview");
  const profiles = [...new Set(o.models.flatMap(m => Object.keys(m.triples)))].sort();
  const total = o.models.reduce((a, m) => a + m.total, 0);
  main.replaceChildren(
    el("h1", {}, "Overview"),
    el("div", {class: "cards"},
      el("div", {class: "card", id: "card-models"}, el("b", {}, o.models.length), "models"),
      el("div", {class: "card"}, el("b", {}, total), "triples asserted"),
      el("div", {class: "card"}, el("b", {}, o.connections === null ? "–" : o.connections), "socket connections"),
      el("div", {class: "card"}, el("b", {}, o.watcher_count), "watchers"),
      el("div", {class: "card"}, el("b", {}, o.deadline_count), "facts to forget")),
    el("h2", {}, "Models"),
    table(["model", ...profiles, "total", "watchers", ""],
      o.models.map(m => [m.name, ...profiles.map(p => m.triples[p] || 0), m.total, m.watchers,
        el("a", {href: "/classes?model=" + encodeURIComponent(m.name)}, "classes")])),
    el("h2", {}, "Next forgetting deadlines"),
    o.deadlines.length === 0 ? el("p", {class: "muted"}, "None pending.") :
      table(["when", "model", "profile", "statement"],
        o.deadlines.map(d => [new Date(d.at).toLocaleTimeString() + " (in " +
          Math.max(0, Math.round((d.at - Date.now()) / 1000)) + " s)", d.model, d.profile,
          el("span", {}, term(d.statement.s), " ", term(d.statement.p), " ", term(d.statement.o))])),
    el("h2", {}, "Watchers", o.watcher_count > o.watchers.length ?
      ` (first ${o.watchers.length} of ${o.watcher_count})` : ""),
    o.watchers.length === 0 ? el("p", {class: "muted"}, "None.") :
      table(["id", "model", "type", "trigger", "variable", "patterns", "subscribers"],
        o.watchers.map(w => [w.id, w.model, w.type, w.trigger, w.var, w.patterns, w.subscribers])),
    el("p", {class: "muted"}, "Also: ", el("a", {href: "/graphs"}, "graphs"),
      ", the SPARQL endpoint ", el("a", {href: "/sparql"}, "/sparql"), ", Pengines at /pengine."));
}

// ---- classes --------------------------------------------------------

function classItem(c) {
  const li = el("li", {});
  const toggle = el("span", {class: "toggle"}, c.subclasses > 0 ? "▸" : "·");
  let open = false, sub = null;
  if (c.subclasses > 0) toggle.addEventListener("click", async () => {
    open = !open;
    toggle.textContent = open ? "▾" : "▸";
    if (open && !sub) {
      const r = await api("classes", {class: c.class.iri});
      sub = el("ul", {class: "tree"}, r.children.map(classItem));
      li.append(sub);
    } else if (sub) sub.hidden = !open;
  });
  li.append(toggle, term(c.class), " ",
    el("span", {class: "muted"}, `${c.instances} instances, ${c.subclasses} subclasses`));
  return li;
}

async function classes() {
  const q = params.get("q");
  main.replaceChildren(el("h1", {}, q ? "Lookup in " : "Classes of ", model));
  if (q) {
    const r = await api("lookup", {q: q});
    main.append(el("h2", {}, `Lookup “${q}”`),
      r.matches.length === 0 ? el("p", {class: "muted"}, "No match.") :
        table(["resource", "kind", ""], r.matches.map(m =>
          [term(m.term), m.kind, el("a", {href: url("/graph", {iri: m.term.iri})}, "graph")])),
      el("p", {}, el("a", {href: url("/classes")}, "the class tree")));
    return;
  }
  const r = await api("classes");
  main.append(el("h2", {}, term(r.class)), el("ul", {class: "tree", id: "tree"}, r.children.map(classItem)));
}

// ---- resource -------------------------------------------------------

function statementRows(list, inferred) {
  return list.map(t => {
    const row = [term(t.s), term(t.p), term(t.o)];
    if (inferred) {
      const q = {s: t.s.iri, p: t.p.iri};
      if (t.o.iri !== undefined) q.o = t.o.iri;
      else { q.lit = t.o.literal; if (t.o.lang) q.lang = t.o.lang; else if (t.o.datatype) q.datatype = t.o.datatype; }
      const box = el("div", {});
      const a = el("a", {href: url("/api/explain", q), class: "why"}, "why");
      a.addEventListener("click", async ev => {
        ev.preventDefault();
        if (box.childNodes.length) { box.replaceChildren(); return; }
        try { box.replaceChildren(explanation(await api("explain", q))); }
        catch (e) { box.replaceChildren(el("span", {class: "error"}, e.message)); }
      });
      row.push(el("span", {}, a, box));
    }
    return row;
  });
}

function explanation(w) {
  if (!w.holds) return el("span", {class: "muted"}, "does not hold");
  if (w.unexplained) return el("span", {class: "muted"}, "holds by a derivation not replayed");
  const tri = t => el("li", {}, term(t.s), " ", term(t.p), " ", term(t.o));
  return el("div", {class: "explanation"},
    el("div", {}, "Facts:"), el("ul", {}, w.facts.map(f => el("li", {},
      term(f.statement.s), " ", term(f.statement.p), " ", term(f.statement.o),
      el("span", {class: "muted"}, " — " + f.origin)))),
    w.axioms.length ? el("div", {}, "Axioms:") : null, el("ul", {}, w.axioms.map(tri)));
}

async function resource() {
  const iri = params.get("iri");
  if (!iri) { main.replaceChildren(el("p", {}, "No resource named.")); return; }
  const r = await api("resource", {iri: iri});
  main.replaceChildren(
    el("h1", {}, r.label, " ", el("small", {class: "muted"}, iri)),
    el("p", {}, el("a", {href: url("/graph", {iri: iri})}, "graph view")),
    el("h2", {}, "Labels"), r.labels.length ? el("p", {}, r.labels.map(l => [term(l), " "])) :
      el("p", {class: "muted"}, "None."),
    el("h2", {}, "Classes"),
    el("p", {}, "Direct: ", r.classes.map(c => [term(c), " "])),
    el("p", {class: "muted"}, "All: ", r.all_classes.map(c => [term(c), " "])),
    el("h2", {}, "Asserted statements", r.asserted_more ? " (first ones)" : ""),
    table(["subject", "predicate", "object"], statementRows(r.asserted, false)),
    el("h2", {}, "Inferred statements", r.inferred_more ? " (first ones)" : ""),
    r.inferred.length ? table(["subject", "predicate", "object", "explanation"],
      statementRows(r.inferred, true), "inferred") : el("p", {class: "muted"}, "None."),
    el("h2", {}, "In each model"),
    table(["model", "known", "direct classes", "asserted statements"],
      r.models.map(m => [el("a", {href: "/resource?model=" + encodeURIComponent(m.model) +
        "&iri=" + encodeURIComponent(iri)}, m.model), m.known ? "yes" : "no",
        el("span", {}, m.classes.map(c => [term(c), " "])), m.statements])));
}

// ---- graph ----------------------------------------------------------

const SVG = "http://www.w3.org/2000/svg";
function svg(tag, attrs, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

async function graph() {
  const iri = params.get("iri");
  if (!iri) { main.replaceChildren(el("p", {}, "No resource named.")); return; }
  const hops = params.get("hops") || "2";
  const g = await api("graph", {iri: iri, hops: hops});
  const W = 900, H = 640, cx = W / 2, cy = H / 2;
  const rings = {};
  g.nodes.forEach(n => (rings[n.hops] = rings[n.hops] || []).push(n));
  const pos = {};
  const step = (Math.min(W, H) / 2 - 40) / Math.max(1, ...Object.keys(rings).map(Number));
  for (const [h, ns] of Object.entries(rings)) {
    const radius = h * step;
    ns.forEach((n, i) => {
      const a = 2 * Math.PI * i / ns.length + h * 0.4;
      pos[n.id] = [cx + radius * Math.cos(a), cy + radius * Math.sin(a)];
    });
  }
  const s = svg("svg", {width: W, height: H, viewBox: `0 0 ${W} ${H}`, id: "graph"});
  for (const e of g.edges) {
    const [x1, y1] = pos[e.from], [x2, y2] = pos[e.to];
    s.append(svg("line", {x1, y1, x2, y2}));
    s.append(svg("text", {x: (x1 + x2) / 2, y: (y1 + y2) / 2, fill: "#68758a"}, e.name));
  }
  for (const n of g.nodes) {
    const [x, y] = pos[n.id];
    const node = svg("g", {class: "node"});
    node.append(svg("circle", {cx: x, cy: y, r: n.hops === 0 ? 11 : 8,
      fill: n.kind === "class" ? "#f0c36b" : (n.hops === 0 ? "#2f6fdd" : "#7fb2ff")}));
    node.append(svg("text", {x: x + 12, y: y + 4}, n.name));
    node.addEventListener("click", () => { location.href = url("/graph", {iri: n.id, hops: hops}); });
    s.append(node);
  }
  main.replaceChildren(el("h1", {}, "Neighbourhood of ", term({iri: iri, name: g.nodes[0].name})),
    el("p", {class: "muted"}, `${g.nodes.length} resources, ${g.edges.length} links, ${hops} hops; click a node to centre it. Hops: `,
      ["1", "2", "3"].map(h => [el("a", {href: url("/graph", {iri: iri, hops: h})}, h), " "])),
    s);
}

// ---- live feed ------------------------------------------------------

function feed() {
  const log = el("div", {id: "feedlog"});
  const status = el("span", {id: "feedstatus"}, "connecting…");
  const counts = {changes: 0, events: 0, dropped: 0};
  const countEl = el("span", {id: "feedcounts"});
  const filter = el("select", {id: "feedfilter"}, el("option", {value: ""}, "all models"));
  const showCounts = () => countEl.textContent =
    ` ${counts.changes} changes, ${counts.events} events, ${counts.dropped} dropped`;
  let ws = null;
  function line(cls, text) {
    log.append(el("div", {class: cls}, new Date().toLocaleTimeString() + " " + text));
    while (log.childNodes.length > 500) log.firstChild.remove();
  }
  function connect() {
    if (ws) ws.close();
    const q = filter.value ? "?model=" + encodeURIComponent(filter.value) : "";
    ws = new WebSocket((location.protocol === "https:" ? "wss://" : "ws://") + location.host + "/api/feed" + q);
    ws.onopen = () => { status.textContent = "live"; };
    ws.onclose = () => { status.textContent = "closed"; };
    ws.onmessage = m => {
      const b = JSON.parse(m.data);
      if (b.dropped > 0) { counts.dropped += b.dropped; line("drop", `feed fell behind: ${b.dropped} dropped`); }
      const shown = b.changes.slice(-200);
      if (b.changes.length > shown.length) line("muted", `… ${b.changes.length - shown.length} more changes in this batch`);
      for (const c of shown)
        line(c.op === "remove" ? "remove" : "add",
          `${c.op === "remove" ? "−" : "+"} [${c.model === null ? "ontology" : c.model}/${c.profile}] ${c.s} ${c.p} ${c.o}`);
      for (const e of b.events) line("event", `event ${e.watcher} [${e.model}]: ${e.content}`);
      for (const c of b.commits) line("muted", "commit " + c);
      counts.changes += b.changes.length; counts.events += b.events.length;
      showCounts(); log.scrollTop = log.scrollHeight;
    };
  }
  filter.addEventListener("change", connect);
  main.replaceChildren(el("h1", {}, "Live feed"),
    el("p", {}, "Model: ", filter, " ", status, countEl), log);
  showCounts();
  api("models").then(o => { for (const m of o.models) filter.append(el("option", {value: m}, m)); })
    .catch(showError);
  connect();
}

// ---- SPARQL ---------------------------------------------------------

async function query() {
  const text = el("textarea", {id: "sparql"},
    params.get("query") || "PREFIX oro: <http://kb.openrobots.org#>\n" +
      "SELECT ?p ?o WHERE { oro:myself ?p ?o }");
  const out = el("div", {id: "results"});
  async function run(ev) {
    if (ev) ev.preventDefault();
    const endpoint = model === "myself" ? "/sparql" : "/sparql/" + encodeURIComponent(model);
    const body = new URLSearchParams({query: text.value});
    const t0 = performance.now();
    const r = await fetch(endpoint, {method: "POST", body: body,
      headers: {"Accept": "application/sparql-results+json"}});
    if (!r.ok) { out.replaceChildren(el("p", {class: "error"}, await r.text())); return; }
    const type = r.headers.get("Content-Type") || "";
    if (!type.includes("json")) { out.replaceChildren(el("pre", {}, await r.text())); return; }
    const j = await r.json();
    const ms = Math.round(performance.now() - t0);
    if (j.boolean !== undefined) { out.replaceChildren(el("p", {}, `ASK: ${j.boolean} (${ms} ms)`)); return; }
    const vars = j.head.vars, rows = j.results.bindings;
    const cell = b => b === undefined ? "" : b.type === "uri" ?
      el("a", {href: url("/resource", {iri: b.value})}, b.value) :
      el("span", {class: b.type === "literal" ? "lit" : ""}, b.value);
    out.replaceChildren(el("p", {class: "muted"}, `${rows.length} rows, ${ms} ms`),
      table(vars, rows.map(row => vars.map(v => cell(row[v])))));
  }
  main.replaceChildren(el("h1", {}, "SPARQL over ", model),
    el("form", {id: "queryform", onsubmit: e => run(e).catch(showError)}, text,
      el("p", {}, el("button", {type: "submit"}, "Run"))), out);
  await run().catch(showError);
}

// ---- start ----------------------------------------------------------

const views = {"/": overview, "/classes": classes, "/resource": resource,
               "/graph": graph, "/feed": feed, "/query": query};

async function start() {
  const path = location.pathname.replace(/\/+$/, "") || "/";
  for (const a of document.querySelectorAll("nav a")) {
    if (a.getAttribute("href") === path) a.classList.add("active");
    if (model !== "myself") a.href = a.getAttribute("href") + "?model=" + encodeURIComponent(model);
  }
  const select = document.getElementById("model");
  select.addEventListener("change", () => {
    const q = new URLSearchParams(location.search);
    q.set("model", select.value);
    location.search = q.toString();
  });
  document.getElementById("lookup").addEventListener("submit", ev => {
    ev.preventDefault();
    location.href = url("/classes", {q: ev.target.q.value});
  });
  const view = views[path];
  try {
    if (!view) throw new Error("No page " + path);
    await view();
    document.body.dataset.ready = "true";
  } catch (e) { showError(e); document.body.dataset.ready = "error"; }
  try {
    const o = await api("models");
    select.replaceChildren(...o.models.map(m => el("option", m === model ? {selected: ""} : {}, m)));
  } catch (e) { /* the page said it already */ }
}

start();
