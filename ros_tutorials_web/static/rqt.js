// rqt in the browser: rqt's plugins on the API of ros_tutorials_web/rqt.py and the viewer's
// WebSocket (/ws). Plain JavaScript, no build step, nothing loaded from elsewhere.
"use strict";

const $ = (id) => document.getElementById(id);
const COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];
const PLOT_KEEP = 20000; // points kept per series
// What the page shows, for a reader (and for the browser tests) to look at.
const state = { tool: null, connected: false, publishers: {}, series: [], bag: null, played: null };
window.rqtState = state;
let socket = null;

// --- the plugin shown ----------------------------------------------------------------------

function choose() {
  const [tool, ...rest] = decodeURIComponent(location.hash.slice(1)).split(":");
  const argument = rest.join(":");
  if (tool === "graph" || tool === "console") {
    // rqt_graph and rqt_console are the viewer's panels.
    location.replace(`./${location.search}#${tool === "graph" ? "graph-section" : "log-section"}`);
    return;
  }
  const known = [...document.querySelectorAll("section.tool")].map((s) => s.id);
  state.tool = known.includes(tool) ? tool : "service_caller";
  for (const id of known) $(id).hidden = id !== state.tool;
  for (const link of document.querySelectorAll("nav#plugins a")) {
    link.classList.toggle("chosen", link.dataset.tool === state.tool);
  }
  document.title = `rqt: ${$(state.tool).querySelector("h2").firstChild.textContent.trim()}`;
  if (state.tool === "service_caller") loadServices();
  if (state.tool === "publisher") loadTopics();
  if (state.tool === "reconfigure") loadNodes("rc-node");
  if (state.tool === "logger_level") loadNodes("ll-node");
  if (state.tool === "plot") {
    for (const field of argument.split(",").filter(Boolean)) addSeries(field);
    loadTopics();
  }
  if (state.tool === "bag" && argument) {
    $("bag-path").value = argument;
    openBag();
  }
}

// --- the server ------------------------------------------------------------------------------

function connect() {
  const url = new URL("ws", location.href);
  url.protocol = location.protocol === "https:" ? "wss:" : "ws:";
  url.search = location.search; // the link's ?token=, where the browser keeps no cookie
  url.hash = "";
  socket = new WebSocket(url);
  socket.onopen = () => {
    state.connected = true;
    setStatus("live", true);
    sendPlot();
    for (const publisher of Object.values(state.publishers)) if (publisher.on) publish(publisher);
  };
  socket.onclose = () => {
    state.connected = false;
    setStatus("disconnected: is rqt still running? retrying\u2026", false);
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => {
    if (typeof event.data !== "string") return; // pictures: the viewer's page shows them
    const message = JSON.parse(event.data);
    if (message.type === "publisher") showPublished(message);
    else if (message.type === "topic" && message.time !== undefined) addPoints(message);
    else if (message.type === "play") showPlayed(message);
  };
}

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function setStatus(text, live) {
  $("status").textContent = text;
  $("status").classList.toggle("live", live);
}

function withToken(path) {
  return path + (path.includes("?") ? "&" : "?") + location.search.slice(1);
}

async function get(path) {
  const answer = await fetch(withToken(path), { credentials: "same-origin" });
  const data = await answer.json().catch(() => ({ error: `HTTP ${answer.status}` }));
  if (!answer.ok) throw new Error(data.error || `HTTP ${answer.status}`);
  return data;
}

// A writing request: a POST of JSON, which the server takes only from this page.
async function post(path, body) {
  const answer = await fetch(withToken(path), {
    method: "POST",
    credentials: "same-origin",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  const data = await answer.json().catch(() => ({ error: `HTTP ${answer.status}` }));
  if (!answer.ok) throw new Error(data.error || `HTTP ${answer.status}`);
  return data;
}

function fillSelect(select, names, prompt) {
  const chosen = select.value;
  select.replaceChildren(new Option(prompt, ""));
  for (const name of names) select.append(new Option(name, name));
  if (names.includes(chosen)) select.value = chosen;
}

// --- a message's form ----------------------------------------------------------------------

// Fields from /api/rqt/interface: one input per field, nested messages as fieldsets.
function buildForm(container, fields) {
  container.replaceChildren();
  for (const field of fields) {
    if (field.kind === "message") {
      const set = document.createElement("fieldset");
      set.dataset.field = field.name;
      const legend = document.createElement("legend");
      legend.textContent = `${field.name} (${field.type})`;
      set.append(legend);
      buildForm(set, field.fields);
      set.prepend(legend);
      container.append(set);
      continue;
    }
    const label = document.createElement("label");
    const name = document.createElement("span");
    name.textContent = field.name;
    let input;
    if (field.kind === "bool") {
      input = document.createElement("select");
      input.append(new Option("false"), new Option("true"));
    } else {
      input = document.createElement("input");
      input.size = field.kind === "array" ? 30 : 16;
    }
    input.value = field.default;
    input.dataset.field = field.name;
    input.name = field.name;
    const type = document.createElement("span");
    type.className = "field-type";
    type.textContent = field.type;
    label.append(name, input, type);
    container.append(label);
  }
}

// The texts typed, nested as the message is: the server reads each as its field's type.
function readForm(container) {
  const values = {};
  for (const child of container.children) {
    if (child.tagName === "FIELDSET") values[child.dataset.field] = readForm(child);
    else if (child.tagName === "LABEL") {
      const input = child.querySelector("[data-field]");
      values[input.dataset.field] = input.value;
    }
  }
  return values;
}

// --- Service Caller ------------------------------------------------------------------------

let services = {};

async function loadServices() {
  try {
    services = await get("api/rqt/services");
    fillSelect($("sc-service"), Object.keys(services), "choose a service\u2026");
    $("sc-error").textContent = "";
  } catch (error) {
    $("sc-error").textContent = error.message;
  }
}

async function chooseService() {
  const service = $("sc-service").value;
  const type = (services[service] || [])[0] || "";
  $("sc-type").textContent = type;
  $("sc-call").disabled = !type;
  $("sc-form").replaceChildren();
  $("sc-response").textContent = "";
  $("sc-time").textContent = "";
  if (!type) return;
  try {
    const form = await get(`api/rqt/interface?type=${encodeURIComponent(type)}`);
    buildForm($("sc-form"), form.request);
    $("sc-error").textContent = "";
  } catch (error) {
    $("sc-error").textContent = error.message;
  }
}

async function callService() {
  const service = $("sc-service").value;
  $("sc-error").textContent = "";
  $("sc-response").textContent = "";
  $("sc-call").disabled = true;
  try {
    const request = readForm($("sc-form"));
    const answer = await post("api/rqt/call", { service, type: services[service][0], request });
    $("sc-response").textContent = answer.yaml || "(an empty response)";
    $("sc-time").textContent = `(${answer.seconds} s)`;
  } catch (error) {
    $("sc-error").textContent = error.message;
  } finally {
    $("sc-call").disabled = false;
  }
}

// --- Message Publisher ---------------------------------------------------------------------

let topics = {};
let nextPublisher = 1;

async function loadTopics() {
  try {
    topics = await get("api/topics");
  } catch (error) {
    return;
  }
  const list = $("pub-topics");
  list.replaceChildren(...Object.keys(topics).map((name) => new Option(name)));
  const types = new Set(Object.values(topics).flat());
  $("pub-types").replaceChildren(...[...types].sort().map((type) => new Option(type)));
  const fields = $("plot-fields");
  fields.replaceChildren(...Object.keys(topics).map((name) => new Option(`${name}/`)));
}

async function addPublisher() {
  const topic = $("pub-topic").value.trim();
  const type = $("pub-type").value.trim() || (topics[topic] || [])[0] || "";
  const rate = Number($("pub-rate").value);
  $("pub-error").textContent = "";
  if (!topic.startsWith("/")) {
    $("pub-error").textContent = "a topic name starts with /";
    return;
  }
  if (!type) {
    $("pub-error").textContent = `no type: ${topic} is not in the graph, type one`;
    return;
  }
  let form;
  try {
    form = await get(`api/rqt/interface?type=${encodeURIComponent(type)}`);
  } catch (error) {
    $("pub-error").textContent = error.message;
    return;
  }
  const id = nextPublisher++;
  const card = document.createElement("div");
  card.className = "publisher";
  card.dataset.id = id;
  card.innerHTML = `<div class="head"><label><input type="checkbox" class="on"> publish</label>
    <span class="what"></span> <label>Freq. <input type="number" class="rate" min="0" max="100"
    step="any" size="5"> Hz</label> <span class="count"></span> <span class="error"></span>
    <button type="button" class="remove">remove</button></div><form class="message-form"></form>`;
  card.querySelector(".what").textContent = `${topic} [${type}]`;
  card.querySelector(".rate").value = rate;
  buildForm(card.querySelector("form"), form.message);
  $("pub-list").append(card);
  const publisher = { id, topic, type, card, on: false, count: 0 };
  state.publishers[id] = publisher;
  card.querySelector(".on").addEventListener("change", (event) => {
    publisher.on = event.target.checked;
    publish(publisher);
  });
  card.querySelector(".rate").addEventListener("change", () => publisher.on && publish(publisher));
  card.querySelector("form").addEventListener("change", () => publisher.on && publish(publisher));
  card.querySelector(".remove").addEventListener("click", () => {
    publisher.on = false;
    publish(publisher);
    card.remove();
    delete state.publishers[id];
  });
}

function publish(publisher) {
  const card = publisher.card;
  send({
    publish: {
      id: publisher.id,
      topic: publisher.topic,
      type: publisher.type,
      message: readForm(card.querySelector("form")),
      rate: Number(card.querySelector(".rate").value),
      on: publisher.on,
    },
  });
}

function showPublished(message) {
  const publisher = state.publishers[message.id];
  if (!publisher) return;
  const card = publisher.card;
  card.querySelector(".error").textContent = message.error || "";
  if (message.error) {
    publisher.on = false;
    card.querySelector(".on").checked = false;
  }
  if (message.count !== undefined && message.count > 0) {
    publisher.count = message.count;
    card.querySelector(".count").textContent = `${message.count} sent`;
  }
}

// --- Parameters (rqt_reconfigure) and Logger Level -------------------------------------------

async function loadNodes(selectId) {
  try {
    fillSelect($(selectId), await get("api/rqt/nodes"), "choose a node\u2026");
  } catch (error) {
    $(selectId === "rc-node" ? "rc-error" : "ll-error").textContent = error.message;
  }
}

async function loadParameters() {
  const node = $("rc-node").value;
  const body = $("rc-params").querySelector("tbody");
  body.replaceChildren();
  $("rc-error").textContent = "";
  if (!node) return;
  try {
    const answer = await get(`api/rqt/params?node=${encodeURIComponent(node)}`);
    for (const parameter of answer.parameters) body.append(parameterRow(node, parameter));
  } catch (error) {
    $("rc-error").textContent = error.message;
  }
}

function parameterRow(node, parameter) {
  const row = document.createElement("tr");
  row.dataset.name = parameter.name;
  const cell = (text, kind) => {
    const td = document.createElement("td");
    td.className = kind;
    td.textContent = text;
    return td;
  };
  const valueCell = document.createElement("td");
  valueCell.className = "value";
  const problem = document.createElement("span");
  problem.className = "row-error";
  const shown = typeof parameter.value === "object" ? JSON.stringify(parameter.value) : String(parameter.value);
  let input;
  if (parameter.type === "boolean") {
    input = document.createElement("input");
    input.type = "checkbox";
    input.checked = parameter.value;
  } else {
    input = document.createElement("input");
    input.className = "value";
    input.value = shown;
  }
  input.disabled = parameter.read_only;
  input.dataset.name = parameter.name;
  valueCell.append(input);
  let slider = null;
  if (parameter.range) {
    slider = document.createElement("input");
    slider.type = "range";
    slider.min = parameter.range.from;
    slider.max = parameter.range.to;
    slider.step = parameter.range.step || (parameter.range.kind === "integer" ? 1 : "any");
    slider.value = parameter.value;
    slider.disabled = parameter.read_only;
    slider.title = `${parameter.range.from} to ${parameter.range.to}`;
    valueCell.prepend(slider);
    slider.addEventListener("input", () => (input.value = slider.value));
    slider.addEventListener("change", () => set());
  }
  valueCell.append(problem);
  const set = async () => {
    const value = input.type === "checkbox" ? String(input.checked) : input.value;
    problem.textContent = "";
    if (value.trim() === "") return; // nothing typed yet
    try {
      await post("api/rqt/param", { node, name: parameter.name, type: parameter.type, value });
      parameter.value = value;
      if (slider) slider.value = value;
    } catch (error) {
      problem.textContent = error.message;
      if (input.type === "checkbox") input.checked = parameter.value;
      else input.value = shown;
      if (slider) slider.value = parameter.value;
    }
  };
  input.addEventListener("change", set);
  const about = parameter.read_only ? `${parameter.description} (read only)` : parameter.description;
  row.append(cell(parameter.name, "name"), valueCell, cell(parameter.type, "type"), cell(about, "description"));
  return row;
}

async function loadLevel() {
  const node = $("ll-node").value;
  $("ll-error").textContent = "";
  $("ll-info").textContent = "";
  $("ll-level").disabled = !node;
  $("ll-level").value = "";
  if (!node) return;
  try {
    const answer = await get(`api/rqt/logger?node=${encodeURIComponent(node)}`);
    $("ll-level").value = answer.level === "UNSET" ? "" : answer.level;
    $("ll-info").textContent = answer.level === "UNSET" ? "unset: the default, INFO, applies" : "";
  } catch (error) {
    $("ll-error").textContent = error.message;
  }
}

async function setLevel() {
  const node = $("ll-node").value;
  const level = $("ll-level").value;
  $("ll-error").textContent = "";
  if (!node || !level) return;
  try {
    const answer = await post("api/rqt/logger", { node, level });
    $("ll-info").textContent = `set to ${answer.level}`;
  } catch (error) {
    $("ll-error").textContent = error.message;
  }
}

// --- Plot ------------------------------------------------------------------------------------

// A series is TOPIC/FIELD/PATH: the topic is the longest prefix the graph knows (else the
// part before the last name), the field the rest with dots, as rqt_plot spells them.
function splitField(text) {
  const names = Object.keys(topics).sort((a, b) => b.length - a.length);
  const topic = names.find((name) => text.startsWith(`${name}/`));
  if (topic) return [topic, text.slice(topic.length + 1).replaceAll("/", ".")];
  const cut = text.lastIndexOf("/");
  return [text.slice(0, cut), text.slice(cut + 1)];
}

function addSeries(text) {
  text = (text || $("plot-field").value).trim().replace(/\/+$/, "");
  $("plot-error").textContent = "";
  if (!text.startsWith("/") || text.lastIndexOf("/") === 0) {
    $("plot-error").textContent = "a field is TOPIC/FIELD, e.g. /turtle1/pose/x";
    return;
  }
  if (state.series.some((s) => s.name === text)) return;
  const [topic, field] = splitField(text);
  const colour = COLOURS[state.series.length % COLOURS.length];
  const series = { name: text, topic, field, colour, points: [], missing: false };
  state.series.push(series);
  const item = document.createElement("li");
  item.innerHTML = `<span class="swatch"></span><span class="label"></span> <button type="button" title="remove">&#x2715;</button>`;
  item.querySelector(".swatch").style.background = colour;
  item.querySelector(".label").textContent = text;
  item.querySelector("button").addEventListener("click", () => {
    state.series = state.series.filter((s) => s !== series);
    item.remove();
    sendPlot();
  });
  series.item = item;
  $("plot-series").append(item);
  $("plot-field").value = "";
  sendPlot();
}

function sendPlot() {
  send({ plot: [...new Set(state.series.map((s) => s.topic))] });
}

function addPoints(message) {
  if ($("plot-pause").checked) return;
  for (const series of state.series) {
    if (series.topic !== message.topic) continue;
    const value = message.numbers[series.field];
    const known = series.field in message.numbers;
    series.missing = !known;
    series.item.querySelector(".label").textContent = known ? series.name : `${series.name} (no such number)`;
    if (!known || value === null) continue;
    series.points.push([message.time, value]);
    if (series.points.length > PLOT_KEEP) series.points.splice(0, series.points.length - PLOT_KEEP);
  }
}

function drawPlot() {
  const canvas = $("plot-canvas");
  const ctx = canvas.getContext("2d");
  const { width, height } = canvas;
  ctx.clearRect(0, 0, width, height);
  const span = Number($("plot-span").value);
  const latest = Math.max(0, ...state.series.map((s) => (s.points.length ? s.points.at(-1)[0] : 0)));
  const end = $("plot-pause").checked && state.pausedAt ? state.pausedAt : latest;
  const start = end - span;
  const visible = state.series.flatMap((s) => s.points.filter(([t]) => t >= start).map(([, v]) => v));
  let low = Number.parseFloat($("plot-ymin").value);
  let high = Number.parseFloat($("plot-ymax").value);
  if (Number.isNaN(low)) low = visible.length ? Math.min(...visible) : 0;
  if (Number.isNaN(high)) high = visible.length ? Math.max(...visible) : 1;
  if (high - low < 1e-9) [low, high] = [low - 0.5, high + 0.5];
  const margin = { left: 56, right: 10, top: 10, bottom: 24 };
  const x = (t) => margin.left + ((t - start) / span) * (width - margin.left - margin.right);
  const y = (v) => height - margin.bottom - ((v - low) / (high - low)) * (height - margin.top - margin.bottom);
  ctx.strokeStyle = "#ddd";
  ctx.fillStyle = "#555";
  ctx.font = "11px sans-serif";
  for (let i = 0; i <= 5; i++) {
    const v = low + ((high - low) * i) / 5;
    ctx.beginPath();
    ctx.moveTo(margin.left, y(v));
    ctx.lineTo(width - margin.right, y(v));
    ctx.stroke();
    ctx.fillText(v.toPrecision(4), 4, y(v) + 4);
  }
  for (let i = 0; i <= 6; i++) {
    const t = start + (span * i) / 6;
    ctx.fillText(`${(t - end).toFixed(1)} s`, x(t) - 14, height - 6);
  }
  ctx.save();
  ctx.beginPath();
  ctx.rect(margin.left, margin.top, width - margin.left - margin.right, height - margin.top - margin.bottom);
  ctx.clip();
  for (const series of state.series) {
    ctx.strokeStyle = series.colour;
    ctx.lineWidth = 1.5;
    ctx.beginPath();
    let first = true;
    for (const [t, v] of series.points) {
      if (t < start - 1) continue;
      if (first) ctx.moveTo(x(t), y(v));
      else ctx.lineTo(x(t), y(v));
      first = false;
    }
    ctx.stroke();
  }
  ctx.restore();
}

function plotLoop() {
  if (state.tool === "plot") drawPlot();
  requestAnimationFrame(plotLoop);
}

// --- Bag -------------------------------------------------------------------------------------

async function openBag() {
  $("bag-error").textContent = "";
  $("bag-info").textContent = "reading\u2026";
  try {
    const bag = await get(`api/rqt/bag?path=${encodeURIComponent($("bag-path").value)}`);
    state.bag = bag;
    state.cursor = null;
    const count = bag.topics.reduce((n, t) => n + t.count, 0);
    $("bag-info").textContent = `${bag.topics.length} topic(s), ${count} message(s), ${bag.duration.toFixed(2)} s`;
    $("bag-start").value = 0;
    $("bag-end").value = bag.duration.toFixed(3);
    $("bag-play").disabled = false;
    const canvas = $("bag-timeline");
    canvas.height = 24 + 22 * bag.topics.length;
    drawTimeline();
  } catch (error) {
    state.bag = null;
    $("bag-info").textContent = "";
    $("bag-error").textContent = error.message;
    $("bag-play").disabled = true;
  }
}

const BAG_LEFT = 220;

function timelineX(canvas, at) {
  const span = Math.max(state.bag.duration, 1e-9);
  return BAG_LEFT + (at / span) * (canvas.width - BAG_LEFT - 10);
}

function drawTimeline() {
  const canvas = $("bag-timeline");
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (!state.bag) return;
  ctx.font = "12px monospace";
  const start = Number($("bag-start").value);
  const end = Number($("bag-end").value);
  ctx.fillStyle = "#eef3ff";
  ctx.fillRect(timelineX(canvas, start), 0, timelineX(canvas, end) - timelineX(canvas, start), canvas.height);
  state.bag.topics.forEach((topic, row) => {
    const top = 8 + row * 22;
    ctx.fillStyle = topic.name === state.bagTopic ? "#22314a" : "#444";
    ctx.fillText(topic.name.slice(0, 26), 4, top + 12);
    ctx.fillStyle = COLOURS[row % COLOURS.length];
    for (const at of topic.times) ctx.fillRect(timelineX(canvas, at), top + 2, 1.5, 14);
  });
  for (const [at, colour] of [[state.cursor, "#d00"], [state.played, "#080"]]) {
    if (at === null || at === undefined) continue;
    ctx.strokeStyle = colour;
    ctx.beginPath();
    ctx.moveTo(timelineX(canvas, at), 0);
    ctx.lineTo(timelineX(canvas, at), canvas.height);
    ctx.stroke();
  }
}

async function timelineClick(event) {
  if (!state.bag) return;
  const canvas = $("bag-timeline");
  const box = canvas.getBoundingClientRect();
  const px = ((event.clientX - box.left) * canvas.width) / box.width;
  const py = ((event.clientY - box.top) * canvas.height) / box.height;
  const row = Math.min(state.bag.topics.length - 1, Math.max(0, Math.floor((py - 8) / 22)));
  const span = Math.max(state.bag.duration, 1e-9);
  const at = Math.min(span, Math.max(0, ((px - BAG_LEFT) / (canvas.width - BAG_LEFT - 10)) * span));
  await showBagMessage(state.bag.topics[row].name, at);
}

async function showBagMessage(topic, at) {
  state.cursor = at;
  state.bagTopic = topic;
  drawTimeline();
  $("bag-error").textContent = "";
  try {
    const path = encodeURIComponent(state.bag.path);
    const answer = await get(`api/rqt/bag/message?path=${path}&topic=${encodeURIComponent(topic)}&at=${at}`);
    $("bag-cursor").textContent = `${answer.at.toFixed(3)} s: ${topic} [${answer.type}] #${answer.index}`;
    $("bag-message").textContent = answer.yaml;
  } catch (error) {
    $("bag-error").textContent = error.message;
  }
}

function play() {
  if (!state.bag) return;
  const start = Number($("bag-start").value);
  let end = Number($("bag-end").value);
  if (end >= state.bag.duration - 0.0005) end = state.bag.duration + 1; // to the end (shown rounded)
  $("bag-play-info").textContent = "playing\u2026";
  $("bag-stop").disabled = false;
  send({ play: { id: Date.now(), path: state.bag.path, start, end } });
}

function stopPlaying() {
  send({ play: null });
  $("bag-stop").disabled = true;
  $("bag-play-info").textContent += " (stopped)";
}

function showPlayed(message) {
  if (message.error) {
    $("bag-error").textContent = message.error;
    $("bag-play-info").textContent = "";
    $("bag-stop").disabled = true;
    return;
  }
  if (message.at !== undefined) state.played = message.at;
  $("bag-play-info").textContent = message.done
    ? `played ${message.count} message(s)`
    : `playing: ${message.count} message(s), at ${state.played.toFixed(2)} s`;
  if (message.done) $("bag-stop").disabled = true;
  drawTimeline();
}

// --- start -----------------------------------------------------------------------------------

$("sc-refresh").addEventListener("click", loadServices);
$("sc-service").addEventListener("change", chooseService);
$("sc-call").addEventListener("click", callService);
$("pub-add").addEventListener("click", addPublisher);
$("pub-topic").addEventListener("change", () => {
  const type = (topics[$("pub-topic").value.trim()] || [])[0];
  if (type) $("pub-type").value = type;
});
$("rc-refresh").addEventListener("click", () => loadNodes("rc-node"));
$("rc-node").addEventListener("change", loadParameters);
$("ll-refresh").addEventListener("click", () => loadNodes("ll-node"));
$("ll-node").addEventListener("change", loadLevel);
$("ll-level").addEventListener("change", setLevel);
$("plot-add").addEventListener("click", () => addSeries());
$("plot-field").addEventListener("keydown", (event) => event.key === "Enter" && addSeries());
$("plot-pause").addEventListener("change", (event) => {
  state.pausedAt = event.target.checked ? Math.max(0, ...state.series.map((s) => (s.points.length ? s.points.at(-1)[0] : 0))) : null;
});
$("bag-open").addEventListener("click", openBag);
$("bag-path").addEventListener("keydown", (event) => event.key === "Enter" && openBag());
$("bag-timeline").addEventListener("click", timelineClick);
$("bag-play").addEventListener("click", play);
$("bag-stop").addEventListener("click", stopPlaying);
for (const id of ["bag-start", "bag-end"]) $(id).addEventListener("change", drawTimeline);
window.addEventListener("hashchange", choose);
choose();
connect();
requestAnimationFrame(plotLoop);
