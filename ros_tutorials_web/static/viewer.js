// The web viewer's page: one WebSocket (/ws, protocol in ros_tutorials_web/viewer.py), five
// panels. Plain JavaScript, no build step, nothing loaded from elsewhere.
"use strict";

const LOG_KEEP = 1000; // log rows kept in the page
const PLOT_SECONDS = 60; // the plot's time span
const LEVELS = ["DEBUG", "INFO", "WARN", "ERROR", "FATAL"];

const $ = (id) => document.getElementById(id);
// What the page shows, for a reader (and for the browser test) to look at.
const state = { frames: {}, pictures: {}, logs: [], topic: null, plot: [], connected: false, live: false, tf: null };
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
  // "live" once the viewer's first graph has come: until then the page knows nothing of the
  // ROS graph, and a glance (or a screenshot) at that moment must not read as an empty one.
  socket.onopen = () => {
    state.connected = true;
    state.live = false;
    setStatus("connected: waiting for the graph\u2026", false);
    if (state.topic) send({ watch: state.topic });
    askFrames();
  };
  socket.onclose = () => {
    state.connected = false;
    state.live = false;
    setStatus("disconnected: is the viewer still running? retrying\u2026", false);
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => {
    if (typeof event.data === "string") {
      const message = JSON.parse(event.data);
      if (message.type === "graph") showGraph(message);
      else if (message.type === "log") addLogs(message.entries);
      else if (message.type === "topic") showTopic(message);
      else if (message.type === "tf") showFrames(message);
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
  const stack = document.createElement("div");
  stack.className = "stack";
  const canvas = document.createElement("canvas");
  canvas.dataset.topic = topic;
  const overlay = document.createElement("canvas"); // the tf frames' axes, over the picture
  overlay.className = "overlay";
  stack.append(canvas, overlay);
  const caption = document.createElement("figcaption");
  caption.textContent = topic;
  figure.append(stack, caption);
  $("pictures").append(figure);
  return { topic, canvas, overlay, caption, busy: false, waiting: null };
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
      if (isTurtlesim(picture)) requestFrames(); // its size may have changed
    } catch (error) {
      picture.caption.textContent = `${header.topic}: cannot show this picture (${error})`;
    }
  }
  picture.busy = false;
}

// The graph's picture topics: each has its figure from the start (its first frame may come
// later: turtlesim sends one when a reader joins, then on each change and every second), and
// a figure whose topic has gone is removed.
function followPictures(pictures) {
  for (const topic of pictures) {
    if (!state.pictures[topic]) {
      const picture = (state.pictures[topic] = addPicture(topic));
      picture.caption.textContent = `${topic} (waiting for its first frame\u2026)`;
    }
  }
  for (const topic of Object.keys(state.pictures)) {
    if (!pictures.includes(topic)) {
      state.pictures[topic].canvas.closest("figure").remove();
      delete state.pictures[topic];
      delete state.frames[topic];
    }
  }
  $("no-pictures").hidden = Object.keys(state.pictures).length > 0;
}

// --- the graph, and the topic list -----------------------------------------------------

function showGraph(message) {
  $("graph").innerHTML = message.svg; // made by the viewer from names it escaped
  followPictures(message.pictures);
  if (!state.live) {
    state.live = true;
    setStatus("live", true);
  }
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

// --- tf: the frame tree, and each frame's axes ------------------------------------------

const TURTLESIM_PIXELS = 500; // turtlesim's canvas: 500 px, 45 px a metre, y up, origin low left
const TURTLESIM_METER = 45;
const AXIS_PIXELS = 40; // an axis's length on the grid, whatever its scale (on turtlesim: 1 m)

function askFrames() {
  send({ tf: { fixed: $("tf-fixed").value } });
}

function isTurtlesim(picture) {
  return picture.topic.endsWith("/_canvas/compressed") && picture.canvas.width > 0;
}

function showFrames(message) {
  state.tf = message;
  const select = $("tf-fixed");
  const chosen = select.value;
  const names = message.frames.map((frame) => frame.name).sort();
  const known = [...select.options].map((option) => option.value).slice(1);
  if (known.join("\n") !== names.join("\n")) {
    select.replaceChildren(new Option("automatic", ""));
    for (const name of names) select.append(new Option(name, name));
    if (chosen && !names.includes(chosen)) select.append(new Option(`${chosen} (not there)`, chosen));
    select.value = chosen;
  }
  select.options[0].textContent = message.fixed && !chosen ? `automatic: ${message.fixed}` : "automatic";
  const info = $("tf-info");
  if (!message.total) info.textContent = "no tf data received";
  else if (message.capped) info.textContent = `${message.total} frames: only the first ${message.frames.length} are shown`;
  else info.textContent = `${message.total} frames, poses in ${message.fixed}`;
  info.classList.toggle("capped", message.capped);
  showTree(message.frames);
  requestFrames();
}

function frameText(frame) {
  if (frame.parent === null) return frame.loop ? "" : "(root)";
  if (frame.static) return `static, ${frame.broadcaster}`;
  const seconds = (value) => value.toFixed(value < 1000 ? 2 : 0);
  const age = frame.age === null ? "?" : frame.age < 0 ? `${seconds(-frame.age)} s in the future` : `${seconds(frame.age)} s old`;
  return `${frame.rate} Hz, ${age}, ${frame.broadcaster}`;
}

function frameItem(frame) {
  const item = document.createElement("li");
  item.dataset.frame = frame.name;
  const name = document.createElement("b");
  name.textContent = frame.name;
  const about = document.createElement("span");
  about.className = "about";
  const problem = document.createElement("div");
  problem.className = "problem";
  item.append(name, about, problem);
  fillFrameItem(item, frame);
  return item;
}

function fillFrameItem(item, frame) {
  const [, about, problem] = item.children;
  about.textContent = " " + frameText(frame);
  if (frame.parent !== null) {
    // What view_frames writes on the frame's edge.
    item.title = `Broadcaster: ${frame.broadcaster}\nAverage rate: ${frame.rate}\n` +
      `Buffer length: ${frame.buffer_length}\nMost recent transform: ${frame.most_recent}\n` +
      `Oldest transform: ${frame.oldest}`;
  }
  problem.textContent = frame.error || "";
  problem.hidden = !frame.error;
}

let treeShape = null; // the frames and their parents the tree shows: rebuilt only when they change

function showTree(frames) {
  const shape = JSON.stringify(frames.map((frame) => [frame.name, frame.parent, frame.loop]));
  const tree = $("tf-tree");
  if (shape === treeShape) {
    // The same tree: new figures in place (a reader's hover and selection stay).
    const items = tree.querySelectorAll("li");
    const byName = new Map(frames.map((frame) => [frame.name, frame]));
    for (const item of items) fillFrameItem(item, byName.get(item.dataset.frame));
    return;
  }
  treeShape = shape;
  const children = new Map();
  const byName = new Map(frames.map((frame) => [frame.name, frame]));
  for (const frame of frames) {
    if (frame.parent !== null && byName.has(frame.parent) && !frame.loop) {
      if (!children.has(frame.parent)) children.set(frame.parent, []);
      children.get(frame.parent).push(frame);
    }
  }
  const list = (level) => {
    const ul = document.createElement("ul");
    for (const frame of level) {
      const item = frameItem(frame);
      const below = children.get(frame.name);
      if (below) item.append(list(below));
      ul.append(item);
    }
    return ul;
  };
  // Roots first (and frames whose parent is past the cap), then the frames caught in a loop.
  const tops = frames.filter((frame) => !frame.loop && (frame.parent === null || !byName.has(frame.parent)));
  tree.replaceChildren(list(tops));
  const looped = frames.filter((frame) => frame.loop);
  if (looped.length) {
    const note = document.createElement("div");
    note.className = "problem";
    note.textContent = "in a loop, no root above them:";
    tree.append(note, list(looped));
  }
}

let framesRequested = false;
function requestFrames() {
  if (!framesRequested) {
    framesRequested = true;
    requestAnimationFrame(() => {
      framesRequested = false;
      drawFrames();
    });
  }
}

function drawAxes(ctx, frames, toScreen, length) {
  ctx.font = "12px monospace";
  ctx.lineCap = "round";
  for (const frame of frames) {
    if (!frame.pose || frame.pose.xyz.includes(null)) continue;
    const [x, y] = toScreen(frame.pose.xyz[0], frame.pose.xyz[1]);
    for (const [axis, colour] of [[frame.pose.x_axis, "#e8141c"], [frame.pose.y_axis, "#12b312"]]) {
      if (axis.includes(null)) continue;
      // A white edge under the colour: seen on turtlesim's blue and on the white grid alike.
      for (const [style, width] of [["#fff", 5], [colour, 3]]) {
        ctx.strokeStyle = style;
        ctx.lineWidth = width;
        ctx.beginPath();
        ctx.moveTo(x, y);
        ctx.lineTo(x + axis[0] * length, y - axis[1] * length); // screen y points down
        ctx.stroke();
      }
    }
    ctx.fillStyle = "#000";
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 3;
    const below = y + 14 < ctx.canvas.height ? y + 14 : y - 6; // a frame on the lower edge
    ctx.strokeText(frame.name, x + 4, below);
    ctx.fillText(frame.name, x + 4, below);
  }
}

function niceStep(span) {
  const rough = span / 8;
  const power = 10 ** Math.floor(Math.log10(rough));
  return [1, 2, 5, 10].map((m) => m * power).find((step) => step >= rough);
}

function drawGrid(canvas, frames, fixed) {
  const width = canvas.width, height = canvas.height;
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, width, height);
  // Auto-scaled: every frame and the fixed frame's origin in view, a metre as wide as high.
  const points = frames.filter((f) => f.pose && !f.pose.xyz.includes(null)).map((f) => f.pose.xyz);
  let [left, right, bottom, top] = [0, 0, 0, 0];
  for (const [x, y] of points) {
    left = Math.min(left, x); right = Math.max(right, x);
    bottom = Math.min(bottom, y); top = Math.max(top, y);
  }
  const margin = Math.max(0.5, 0.1 * Math.max(right - left, top - bottom));
  left -= margin; right += margin; bottom -= margin; top += margin;
  const scale = Math.min(width / (right - left), height / (top - bottom));
  const cx = (left + right) / 2, cy = (bottom + top) / 2;
  const toScreen = (x, y) => [width / 2 + (x - cx) * scale, height / 2 - (y - cy) * scale];
  const step = niceStep(Math.max(width, height) / scale);
  ctx.font = "10px monospace";
  ctx.fillStyle = "#999";
  ctx.lineWidth = 1;
  const [x0, y0] = [cx - width / 2 / scale, cy - height / 2 / scale];
  for (let gx = Math.ceil(x0 / step) * step; gx <= x0 + width / scale; gx += step) {
    const [sx] = toScreen(gx, 0);
    ctx.strokeStyle = Math.abs(gx) < step / 1e6 ? "#888" : "#e4e4e4";
    ctx.beginPath(); ctx.moveTo(sx, 0); ctx.lineTo(sx, height); ctx.stroke();
    ctx.fillText(`${+gx.toPrecision(6)}`, sx + 2, height - 3);
  }
  for (let gy = Math.ceil(y0 / step) * step; gy <= y0 + height / scale; gy += step) {
    const [, sy] = toScreen(0, gy);
    ctx.strokeStyle = Math.abs(gy) < step / 1e6 ? "#888" : "#e4e4e4";
    ctx.beginPath(); ctx.moveTo(0, sy); ctx.lineTo(width, sy); ctx.stroke();
    ctx.fillText(`${+gy.toPrecision(6)}`, 2, sy - 2);
  }
  const caption = `grid ${+step.toPrecision(6)} m, seen from above (${fixed}: x right, y up)`;
  ctx.fillStyle = "#fffd";
  ctx.fillRect(0, 0, ctx.measureText(caption).width + 8, 16);
  ctx.fillStyle = "#555";
  ctx.fillText(caption, 4, 12);
  drawAxes(ctx, frames, toScreen, AXIS_PIXELS);
}

function drawFrames() {
  const tf = state.tf;
  const frames = tf ? tf.frames : [];
  const turtlesims = Object.values(state.pictures).filter(isTurtlesim);
  const onCanvas = tf !== null && tf.fixed === "world" && turtlesims.length > 0;
  for (const picture of Object.values(state.pictures)) {
    const overlay = picture.overlay;
    if (overlay.width !== picture.canvas.width) overlay.width = picture.canvas.width;
    if (overlay.height !== picture.canvas.height) overlay.height = picture.canvas.height;
    const ctx = overlay.getContext("2d");
    ctx.clearRect(0, 0, overlay.width, overlay.height);
    if (onCanvas && isTurtlesim(picture)) {
      const pixels = (overlay.width / TURTLESIM_PIXELS) * TURTLESIM_METER;
      const high = overlay.height - overlay.height / TURTLESIM_PIXELS; // y = 0 m: the last row
      drawAxes(ctx, frames, (x, y) => [x * pixels, high - y * pixels], pixels);
    }
  }
  $("tf-on-canvas").hidden = !onCanvas;
  $("tf-view").hidden = onCanvas || !tf || !tf.total;
  if (!$("tf-view").hidden) drawGrid($("tf-view"), frames, tf.fixed);
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
$("tf-fixed").addEventListener("change", askFrames);
$("log-level").addEventListener("change", showLogs);
$("log-node").addEventListener("change", showLogs);
$("log-clear").addEventListener("click", () => {
  state.logs = [];
  showLogs();
});
window.addEventListener("resize", requestPlot);
connect();
