"use strict";
// The page's whole logic: create a game, follow its event stream, draw the view the server sends,
// and send the person's clicks as moves naming the decision they were made at.

const $ = (id) => document.getElementById(id);
const PAGE = document.body.dataset.page;
const MODES = ["ja", "en", "ascii"];
let tiles = MODES.includes(localStorage.getItem("rinshan-tiles")) ? localStorage.getItem("rinshan-tiles") : "en";
let game = null;   // the id
let view = null;   // the last view
let stream = null;
let busy = false, again = false;
let acting = false; // a move is on its way: further clicks wait for the next view

async function api(method, url, body) {
  const init = { method, headers: {} };
  if (body !== undefined) {
    init.headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  const r = await fetch(url, init);
  const text = await r.text();
  let data;
  try { data = JSON.parse(text); } catch (_) { data = { error: text }; }
  if (!r.ok) throw new Error(data.error || ("HTTP " + r.status));
  return data;
}

function showError(e) {
  const box = $("error");
  if (!box) return;
  box.textContent = e ? String(e.message || e) : "";
  box.hidden = !e;
}

async function loadSprite() {
  const r = await fetch("/api/sprite/" + tiles);
  $("sprite").innerHTML = await r.text();
  document.body.dataset.tiles = tiles;
}

// Every variant the server was built with, its spec's description as the tooltip; the form
// offers as many seats and agents as the chosen one has seats.
function fillVariants(names, descriptions, seats) {
  const sel = document.querySelector("select[name=variant]");
  names.forEach((n) => {
    const o = document.createElement("option");
    o.value = n; o.textContent = n; o.title = descriptions[n] || "";
    sel.appendChild(o);
  });
  sel.value = "red";
  sel.addEventListener("change", () => fitSeats(seats[sel.value] || 4));
  fitSeats(seats[sel.value] || 4);
}

// A disabled select is not submitted: a three-player game sends one agent fewer.
function fitSeats(n) {
  const want = PAGE === "play" ? n - 1 : n;
  document.querySelectorAll("select.agent").forEach((a, i) => { a.hidden = a.disabled = i >= want; });
  // Three players have no North.
  const wind = document.querySelector("select[name=wind]");
  if (!wind) return;
  wind.querySelectorAll("option").forEach((o) => { o.hidden = o.disabled = Number(o.value) >= n; });
  if (Number(wind.value) >= n) wind.value = "0";
}

function fillAgents(names) {
  const defaults = ["rule", "greedy", "defensive", "rule"];
  document.querySelectorAll("select.agent").forEach((sel, i) => {
    names.forEach((n) => {
      const o = document.createElement("option");
      // The server's MJAI bots come as mjai:NAME.
      o.value = n; o.textContent = n.startsWith("mjai:") ? n.slice(5) + " (MJAI bot)" : n;
      sel.appendChild(o);
    });
    sel.value = defaults[i % defaults.length];
  });
}

async function start(ev) {
  ev.preventDefault();
  showError(null);
  const f = new FormData($("setup"));
  const body = {
    variant: f.get("variant"),
    mode: f.get("mode"),
    agents: f.getAll("agent"),
    delay_ms: Number(f.get("delay")),
  };
  // The wind, not a seat: the seed draws the first dealer, so a seat number fixes no wind.
  if (PAGE === "play") body.wind = Number(f.get("wind"));
  // A seed travels as a string: a JavaScript number loses digits above 2^53.
  if (f.get("seed")) body.seed = String(f.get("seed")).trim();
  try {
    const v = await api("POST", "/api/games", body);
    game = v.id;
    $("setup").hidden = true;
    $("game").hidden = false;
    if (stream) stream.close();
    stream = new EventSource("/api/games/" + game + "/events");
    stream.addEventListener("change", refresh);
    await refresh();
  } catch (e) { showError(e); }
}

async function refresh() {
  if (!game) return;
  if (busy) { again = true; return; }
  busy = true;
  do {
    again = false;
    const id = game;
    try {
      const v = await api("GET", "/api/games/" + id + "?tiles=" + tiles);
      // A view of a game the person has left is dropped.
      if (id === game) { view = v; draw(); }
    } catch (e) { showError(e); }
  } while (again && game);
  busy = false;
}

function draw() {
  const v = view;
  $("board").innerHTML = v.svg;
  document.body.dataset.phase = v.phase;
  document.body.dataset.step = String(v.step);
  const who = v.names[v.current];
  const turn = { human: "Your turn", agent: who + " to move", result: "Round over", over: "Game over" }[v.phase];
  $("status").innerHTML = "";
  const h = document.createElement("h3");
  h.textContent = v.round + (v.honba ? " · " + v.honba + " honba" : "") + " — " + turn;
  $("status").appendChild(h);
  const scores = document.createElement("p");
  scores.className = "scores";
  const points = v.result && v.result.final_scores ? v.result.final_scores : v.scores;
  scores.textContent = v.names.map((n, p) => n + " " + points[p]).join(" · ");
  $("status").appendChild(scores);
  // The rule set played, so that a page left open says which rules its scores follow.
  const rules = document.createElement("p");
  rules.className = "rules";
  rules.textContent = "Rules: " + v.variant + " (" + v.mode + ")";
  rules.title = v.rules;
  $("status").appendChild(rules);
  if (v.seed !== null && v.seed !== undefined) {
    const seed = document.createElement("p");
    seed.className = "seed";
    seed.textContent = "Seed " + v.seed;
    $("status").appendChild(seed);
  }
  if ($("actions")) drawActions(v);
  if ($("odds")) drawOdds(v);
  drawResult(v);
  const ev = $("events");
  ev.innerHTML = "";
  v.events.slice().reverse().forEach((t) => { const li = document.createElement("li"); li.textContent = t; ev.appendChild(li); });
  const dl = $("download");
  dl.hidden = !v.log;
  if (v.log) dl.href = "/api/games/" + game + "/log";
}

function drawActions(v) {
  const box = $("actions");
  box.innerHTML = "";
  box.hidden = v.phase !== "human" && v.phase !== "agent";
  if (v.phase !== "human") {
    box.textContent = v.phase === "agent" ? "Waiting for " + v.names[v.current] + "…" : "";
    // The look-ahead may think a while: a spinner says it is at work.
    if (v.phase === "agent") { const sp = document.createElement("span"); sp.className = "spinner"; box.appendChild(sp); }
    return;
  }
  const discards = v.legal.filter((c) => c.tile);
  const tsumogiri = v.legal.find((c) => c.name === "tsumogiri");
  // Discards are made by clicking a tile of the hand.
  document.querySelectorAll('#board .tile[data-seat="' + v.seat + '"]').forEach((g) => {
    const zone = g.dataset.zone;
    if (zone !== "hand" && zone !== "drawn") return;
    const choice = zone === "drawn" && tsumogiri ? tsumogiri : discards.find((c) => c.tile === g.dataset.tile);
    if (!choice) return;
    g.classList.add("playable");
    g.setAttribute("role", "button");
    g.addEventListener("click", () => act(choice.id));
  });
  if (discards.length || tsumogiri) {
    const hint = document.createElement("p");
    hint.className = "hint";
    hint.textContent = "Click a tile of your hand to discard it.";
    box.appendChild(hint);
  }
  v.legal.filter((c) => !c.tile && c.name !== "tsumogiri").forEach((c) => {
    const b = document.createElement("button");
    b.type = "button";
    b.className = "action " + c.name;
    b.dataset.action = c.name;
    b.textContent = c.label;
    b.addEventListener("click", () => act(c.id));
    box.appendChild(b);
  });
}

// The odds of each discard at the person's own turn, drawing alone from the tiles they cannot
// see (the server plays the draws out); asked once per decision, only while the box is ticked.
let oddsStep = null;
async function drawOdds(v) {
  const box = $("odds");
  const own = v.phase === "human" && v.legal.some((c) => c.tile || c.name === "tsumogiri");
  if (!$("odds-on").checked || !own) { box.replaceChildren(); oddsStep = null; return; }
  if (oddsStep === v.step) return;
  oddsStep = v.step;
  box.textContent = "working out the odds…";
  let o;
  try { o = await api("GET", "/api/games/" + game + "/outlook"); } catch (e) { box.textContent = String(e.message || e); return; }
  if (oddsStep !== v.step) return;
  const t = document.createElement("table");
  t.className = "odds-table";
  const head = document.createElement("tr");
  ["discard", "shanten", "tenpai", "win"].forEach((h) => { const th = document.createElement("th"); th.textContent = h; head.appendChild(th); });
  t.appendChild(head);
  const pct = (p) => (100 * p).toFixed(1) + "%";
  for (const d of o.discards.slice(0, 8)) {
    const tr = document.createElement("tr");
    tr.dataset.tile = d.discard;
    [d.discard, String(d.shanten), pct(d.tenpai[o.draws - 1]), pct(d.win[o.draws - 1])].forEach((x) => {
      const td = document.createElement("td"); td.textContent = x; tr.appendChild(td);
    });
    t.appendChild(tr);
  }
  const note = document.createElement("p");
  note.className = "note";
  note.textContent = "By your last draw (" + o.draws + " left), drawing alone: others' wins and calls are not counted.";
  box.replaceChildren(t, note);
}

function drawResult(v) {
  const box = $("result");
  if (!v.result) { box.hidden = true; box.innerHTML = ""; return; }
  box.hidden = false;
  box.innerHTML = "";
  const h = document.createElement("h3");
  const r = v.result;
  h.textContent = r.wins.length
    ? r.wins.map((w) => v.names[w.seat] + (w.from === null ? " tsumo" : " ron from " + v.names[w.from])).join("; ")
    : (r.draw || "Draw");
  box.appendChild(h);
  r.wins.forEach((w) => {
    const p = document.createElement("p");
    p.textContent = w.yaku.join(", ") + " — " + (w.yakuman ? "yakuman ×" + w.yakuman : w.han + " han " + w.fu + " fu");
    box.appendChild(p);
  });
  const t = document.createElement("table");
  t.className = "deltas";
  v.names.forEach((n, p) => {
    const tr = document.createElement("tr");
    tr.innerHTML = "<td></td><td class='num'></td>";
    tr.children[0].textContent = n;
    tr.children[1].textContent = (r.deltas[p] > 0 ? "+" : "") + r.deltas[p];
    if (r.uma) {
      const td = document.createElement("td");
      td.className = "num uma";
      td.textContent = "uma " + (r.uma[p] > 0 ? "+" : "") + r.uma[p];
      tr.appendChild(td);
    }
    t.appendChild(tr);
  });
  box.appendChild(t);
  if (r.ranks) {
    const order = [0, 1, 2, 3].sort((a, b) => r.ranks[a] - r.ranks[b]);
    const ol = document.createElement("ol");
    ol.className = "ranking";
    order.forEach((p) => { const li = document.createElement("li"); li.textContent = v.names[p] + " — " + r.final_scores[p]; ol.appendChild(li); });
    box.appendChild(ol);
  }
  if (v.phase === "result" && PAGE === "play") {
    const b = document.createElement("button");
    b.type = "button";
    b.id = "next";
    b.className = "action next";
    b.textContent = "Next round";
    b.addEventListener("click", async () => {
      if (acting) return;
      acting = true;
      b.disabled = true;
      try { await api("POST", "/api/games/" + game + "/next"); } catch (e) { showError(e); }
      acting = false;
      refresh();
    });
    box.appendChild(b);
  }
}

async function act(id) {
  if (acting) return;
  acting = true;
  document.querySelectorAll("#actions button").forEach((b) => { b.disabled = true; });
  showError(null);
  try {
    await api("POST", "/api/games/" + game + "/actions", { action: id, step: view.step });
  } catch (e) { showError(e); }
  acting = false;
  refresh();
}

// Shows a replay page the server drew (from an upload or a saved game).
async function showReplay(r) {
  const text = await r.text();
  if (!r.ok) { let m = text; try { m = JSON.parse(text).error; } catch (_) {} throw new Error(m); }
  const frame = $("viewer");
  // The page is ours, but it holds names from the log: keep it in a sandbox.
  frame.setAttribute("sandbox", "allow-scripts");
  frame.srcdoc = text;
  frame.hidden = false;
}

async function openReplay(ev) {
  ev.preventDefault();
  showError(null);
  const file = $("file").files[0];
  if (!file) { showError("choose a log file first"); return; }
  const seat = $("review-seat").value;
  const url = seat === "" ? "/api/replay" : "/api/review?seat=" + seat;
  $("open").disabled = true;
  try {
    await showReplay(await fetch(url, { method: "POST", body: await file.text() }));
  } catch (e) { showError(e); }
  $("open").disabled = false;
}

// The games this server finished and kept, newest first (none where it keeps none).
async function listSaved() {
  const r = await fetch("/api/saved");
  if (!r.ok) return;
  const games = (await r.json()).games;
  if (!games.length) return;
  const list = $("saved-list");
  for (const g of games) {
    const li = document.createElement("li");
    const b = document.createElement("button");
    b.type = "button";
    b.className = "saved-game";
    b.textContent = new Date(g.written * 1000).toLocaleString() + " (" + Math.round(g.bytes / 1024) + " KB)";
    b.addEventListener("click", async () => {
      showError(null);
      try { await showReplay(await fetch("/api/saved/" + encodeURIComponent(g.name) + "/replay")); } catch (e) { showError(e); }
    });
    const a = document.createElement("a");
    a.href = "/api/saved/" + encodeURIComponent(g.name);
    a.download = g.name;
    a.textContent = "log";
    li.append(b, " ", a);
    list.appendChild(li);
  }
  $("saved").hidden = false;
}

async function init() {
  if ($("odds-on")) $("odds-on").addEventListener("change", () => { oddsStep = null; if (view) drawOdds(view); });
  document.querySelectorAll("[data-nav]").forEach((a) => a.classList.toggle("here", a.dataset.nav === PAGE));
  $("tiles").value = tiles;
  $("tiles").addEventListener("change", async (e) => {
    tiles = e.target.value;
    localStorage.setItem("rinshan-tiles", tiles);
    await loadSprite();
    refresh();
  });
  await loadSprite();
  if (PAGE === "replay") {
    $("upload").addEventListener("submit", openReplay);
    await listSaved();
    document.body.dataset.ready = "1";
    return;
  }
  const info = await api("GET", "/api/agents");
  fillVariants(info.variants, info.variant_descriptions, info.variant_seats || {});
  fillAgents(info.agents);
  $("setup").addEventListener("submit", start);
  $("leave").addEventListener("click", () => {
    if (stream) stream.close();
    if (game) fetch("/api/games/" + game, { method: "DELETE" });
    game = null;
    $("game").hidden = true;
    $("setup").hidden = false;
  });
  document.body.dataset.ready = "1";
}

init().catch(showError);
