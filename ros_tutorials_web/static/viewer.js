// The web viewer's page: one WebSocket (/ws, protocol in ros_tutorials_web/viewer.py), four
// panels. Plain JavaScript, no build step, nothing loaded from elsewhere.
"use strict";

const LOG_KEEP = 1000; // log rows kept in the page
const PLOT_SECONDS = 60; // the plot's time span
const LEVELS = ["DEBUG", "INFO", "WARN", "ERROR", "FATAL"];

const $ = (id) => document.getElementById(id);
// What the page shows, for a reader (and for the browser test) to look at.
const state = { frames: {}, pictures: {}, logs: [], topic: null, plot: [], connected: false };
window.viewerState = state;
let socket = null;

// --- the connection ------------------------------------------------------------------

function connect() {
  // Relative to the page: works behind a cloud editor's forwarded-port proxy too.
  const url = new URL("ws", location.href);
  url.protocol = location.protocol === "https:" ? "wss:" : "ws:";
  // The link's ?token=, where a browser keeps no cookie (the viewer set one otherwise).
  url.search = location.search;
  socket = new WebSocket(url);
  socket.binaryType = "arraybuffer";
  socket.onopen = () => {
    state.connected = true;
    setStatus("live", true);
    if (state.topic) send({ watch: state.topic });
  };
  socket.onclose = () => {
    state.connected = false;
    setStatus("disconnected: is the viewer still running? retrying\u2026", false);
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => {
    if (typeof event.data === "string") {
      const message = JSON.parse(event.data);
      if (message.type === "graph") showGraph(message);
      else if (message.type === "log") addLogs(message.entries);
      else if (message.type === "topic") showTopic(message);
    } else {
      showPicture(event.data);
    }
  };
}

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function setStatus(text, live) {
  $("status").textContent = text;
  $("status").classList.toggle("live", live);
}

// --- pictures (every turtlesim's canvas) ---------------------------------------------

function showPicture(buffer) {
  const length = new DataView(buffer).getUint32(0);
  const header = JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 4, length)));
  const blob = new Blob([new Uint8Array(buffer, 4 + length)], { type: header.mime });
  let picture = state.pictures[header.topic];
  if (!picture) picture = state.pictures[header.topic] = addPicture(header.topic);
  // One decode at a time per picture; a frame that comes meanwhile replaces the waiting one.
  picture.waiting = { header, blob };
  if (!picture.busy) drawPicture(picture);
}

function addPicture(topic) {
  $("no-pictures").hidden = true;
  const figure = document.createElement("figure");
  const canvas = document.createElement("canvas");
  canvas.dataset.topic = topic;
  const caption = document.createElement("figcaption");
  caption.textContent = topic;
  figure.append(canvas, caption);
  $("pictures").append(figure);
  return { topic, canvas, caption, busy: false, waiting: null };
}

async function drawPicture(picture) {
  picture.busy = true;
  while (picture.waiting) {
    const { header, blob } = picture.waiting;
    picture.waiting = null;
    try {
      const bitmap = await createImageBitmap(blob);
      if (picture.canvas.width !== bitmap.width) picture.canvas.width = bitmap.width;
      if (picture.canvas.height !== bitmap.height) picture.canvas.height = bitmap.height;
      picture.canvas.getContext("2d").drawImage(bitmap, 0, 0);
      bitmap.close();
      state.frames[header.topic] = { count: header.count, stamp: header.stamp, shown: Date.now() / 1000 };
      picture.caption.textContent = `${header.topic} (frame ${header.count})`;
    } catch (error) {
      picture.caption.textContent = `${header.topic}: cannot show this picture (${error})`;
    }
  }
  picture.busy = false;
}

function forgetPictures(pictures) {
  for (const topic of Object.keys(state.pictures)) {
    if (!pictures.includes(topic)) {
      state.pictures[topic].canvas.parentElement.remove();
      delete state.pictures[topic];
      delete state.frames[topic];
    }
  }
  $("no-pictures").hidden = Object.keys(state.pictures).length > 0;
}

// --- the graph, and the topic list -----------------------------------------------------

function showGraph(message) {
  $("graph").innerHTML = message.svg; // made by the viewer from names it escaped
  forgetPictures(message.pictures);
  const select = $("topic-select");
  const chosen = select.value;
  select.replaceChildren(new Option("choose a topic\u2026", ""));
  for (const [name, types] of Object.entries(message.topics)) {
    select.append(new Option(`${name} [${types.join(", ")}]`, name));
  }
  if (chosen && !(chosen in message.topics)) select.append(new Option(`${chosen} (gone)`, chosen));
  select.value = chosen;
}

// --- one topic: its newest message and a plot ----------------------------------------------

function watch(topic) {
  state.topic = topic || null;
  state.plot = [];
  state.message = null;
  $("topic-message").textContent = "";
  $("topic-info").textContent = topic ? "waiting for a message\u2026" : "";
  $("field-select").replaceChildren(new Option("a number\u2026", ""));
  send({ watch: state.topic });
  drawPlot();
}

function showTopic(message) {
  if (message.topic !== state.topic) return;
  state.message = message;
  $("topic-message").textContent = message.yaml;
  $("topic-info").textContent = `${message.type_name}, message ${message.count}`;
  const select = $("field-select");
  const fields = Object.keys(message.numbers);
  if (select.options.length !== fields.length + 1) {
    const chosen = select.value;
    select.replaceChildren(new Option("a number\u2026", ""));
    for (const field of fields) select.append(new Option(field, field));
    select.value = fields.includes(chosen) ? chosen : "";
  }
  const field = select.value;
  if (field && field in message.numbers) {
    const value = message.numbers[field];
    const now = performance.now() / 1000;
    state.plot.push([now, value]);
    while (state.plot.length && state.plot[0][0] < now - PLOT_SECONDS) state.plot.shift();
    $("field-value").textContent = value === null ? "not a number" : String(value);
    requestPlot();
  }
}

let plotRequested = false;
function requestPlot() {
  if (!plotRequested) {
    plotRequested = true;
    requestAnimationFrame(() => {
      plotRequested = false;
      drawPlot();
    });
  }
}

function drawPlot() {
  const canvas = $("plot");
  const width = (canvas.width = canvas.clientWidth || 600);
  const height = canvas.height;
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, width, height);
  const points = state.plot.filter(([, v]) => v !== null);
  if (points.length < 1) return;
  let low = Math.min(...points.map(([, v]) => v));
  let high = Math.max(...points.map(([, v]) => v));
  if (high - low < 1e-9) {
    low -= 1;
    high += 1;
  }
  const end = state.plot[state.plot.length - 1][0];
  const left = 60, bottom = height - 20;
  const x = (t) => left + ((t - (end - PLOT_SECONDS)) / PLOT_SECONDS) * (width - left - 10);
  const y = (v) => 10 + ((high - v) / (high - low)) * (bottom - 10);
  ctx.strokeStyle = "#ccc";
  ctx.fillStyle = "#555";
  ctx.font = "11px monospace";
  for (const v of [low, (low + high) / 2, high]) {
    ctx.beginPath();
    ctx.moveTo(left, y(v));
    ctx.lineTo(width - 10, y(v));
    ctx.stroke();
    ctx.fillText(v.toPrecision(4), 2, y(v) + 4);
  }
  ctx.fillText(`${PLOT_SECONDS} s`, left, height - 5);
  ctx.fillText("now", width - 35, height - 5);
  ctx.strokeStyle = "#1f5fbf";
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  let drawing = false;
  for (const [t, v] of state.plot) {
    if (v === null) {
      drawing = false;
      continue;
    }
    if (drawing) ctx.lineTo(x(t), y(v));
    else ctx.moveTo(x(t), y(v));
    drawing = true;
  }
  ctx.stroke();
}

// --- the log -----------------------------------------------------------------------------

const logNodes = new Set();

function shown(entry) {
  const level = $("log-level").value;
  const node = $("log-node").value;
  return LEVELS.indexOf(entry.level) >= LEVELS.indexOf(level) && (!node || entry.node === node);
}

function logRow(entry) {
  const row = document.createElement("tr");
  row.className = entry.level;
  const time = new Date(entry.time * 1000).toLocaleTimeString([], { hour12: false });
  for (const text of [time, entry.level, entry.node, entry.msg]) {
    const cell = document.createElement("td");
    cell.textContent = text;
    row.append(cell);
  }
  return row;
}

function addLogs(entries) {
  const scroller = document.querySelector(".log-scroll");
  const atBottom = scroller.scrollTop + scroller.clientHeight >= scroller.scrollHeight - 5;
  const body = document.querySelector("#log tbody");
  for (const entry of entries) {
    state.logs.push(entry);
    if (!logNodes.has(entry.node)) {
      logNodes.add(entry.node);
      $("log-node").append(new Option(entry.node, entry.node));
    }
    if (shown(entry)) body.append(logRow(entry));
  }
  if (state.logs.length > LOG_KEEP) state.logs.splice(0, state.logs.length - LOG_KEEP);
  while (body.rows.length > LOG_KEEP) body.deleteRow(0);
  if (atBottom) scroller.scrollTop = scroller.scrollHeight;
}

function showLogs() {
  const body = document.querySelector("#log tbody");
  body.replaceChildren(...state.logs.filter(shown).map(logRow));
}

// --- start -------------------------------------------------------------------------------

$("topic-select").addEventListener("change", (event) => watch(event.target.value));
$("field-select").addEventListener("change", () => {
  state.plot = [];
  drawPlot();
});
$("log-level").addEventListener("change", showLogs);
$("log-node").addEventListener("change", showLogs);
$("log-clear").addEventListener("click", () => {
  state.logs = [];
  showLogs();
});
window.addEventListener("resize", requestPlot);
connect();
