// joint_state_publisher_gui's sliders: one per movable joint, Randomize and Center.
// The server (joint_state_publisher_gui.py) sends {"joints": [...]} for a new robot and
// {"positions": {...}} when a value changed; a slider sends {"set": {JOINT: VALUE}}.
"use strict";

const RANGE = 10000; // slider steps, as the Qt window's
const sliders = document.getElementById("sliders");
const status = document.getElementById("status");
const error = document.getElementById("error");
const joints = new Map(); // name -> {joint, input, value}
let socket = null;

function send(message) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify(message));
}

function toSlider(joint, position) {
  return Math.round(((position - joint.min) * RANGE) / (joint.max - joint.min || 1));
}

function toValue(joint, slider) {
  return joint.min + ((joint.max - joint.min) * slider) / RANGE;
}

function show(name, position) {
  const entry = joints.get(name);
  if (!entry) return;
  entry.input.value = toSlider(entry.joint, position);
  entry.value.textContent = position.toFixed(3);
}

function draw(list) {
  sliders.replaceChildren();
  joints.clear();
  for (const joint of list) {
    const box = document.createElement("div");
    box.className = "joint";
    box.dataset.joint = joint.name;
    const row = document.createElement("div");
    row.className = "row";
    const label = document.createElement("span");
    label.textContent = joint.name;
    const value = document.createElement("span");
    value.className = "value";
    row.append(label, value);
    const input = document.createElement("input");
    input.type = "range";
    input.min = 0;
    input.max = RANGE;
    input.setAttribute("aria-label", joint.name);
    input.addEventListener("input", () => {
      const position = toValue(joint, Number(input.value));
      value.textContent = position.toFixed(3);
      send({ set: { [joint.name]: position } });
    });
    box.append(row, input);
    sliders.append(box);
    joints.set(joint.name, { joint, input, value });
    show(joint.name, joint.position);
  }
  status.textContent = list.length
    ? `${list.length} movable joint${list.length === 1 ? "" : "s"}`
    : "This robot has no movable joints (or no robot_description yet).";
}

function connect() {
  const scheme = location.protocol === "https:" ? "wss:" : "ws:";
  socket = new WebSocket(`${scheme}//${location.host}/ws`);
  socket.onopen = () => { error.textContent = ""; };
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.joints) draw(message.joints);
    if (message.positions) {
      for (const [name, position] of Object.entries(message.positions)) show(name, position);
      error.textContent = "";
    }
    if (message.error) error.textContent = message.error;
  };
  socket.onclose = () => {
    status.textContent = "Disconnected: joint_state_publisher_gui stopped (reload once it runs again).";
  };
}

document.getElementById("randomize").addEventListener("click", () => send({ randomize: true }));
document.getElementById("center").addEventListener("click", () => send({ center: true }));
connect();
