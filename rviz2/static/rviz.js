// rviz2's 3D view: the scene the server streams (rviz2/scene.py), drawn with three.js.
// ROS's axes: x forward, y left, z up; every display's object hangs in the fixed frame,
// placed each animation frame at the pose tf gives its message's frame.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { STLLoader } from "three/addons/loaders/STLLoader.js";
import { ColladaLoader } from "three/addons/loaders/ColladaLoader.js";
import { CSS2DObject, CSS2DRenderer } from "three/addons/renderers/CSS2DRenderer.js";

THREE.Object3D.DEFAULT_UP.set(0, 0, 1);
const $ = (id) => document.getElementById(id);
const view = $("view");

// --- three.js: renderer, camera, controls, the fixed frame's root
// Without a GPU (WebGL drawn in software: SwiftShader, llvmpipe) every pixel costs CPU: no
// antialiasing, one pixel per CSS pixel.
function softwareWebGL() {
  const gl = document.createElement("canvas").getContext("webgl2");
  const info = gl && gl.getExtension("WEBGL_debug_renderer_info");
  const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : "";
  return /swiftshader|llvmpipe|software/i.test(name);
}
const software = softwareWebGL();
const renderer = new THREE.WebGLRenderer({ antialias: !software, preserveDrawingBuffer: true });
renderer.setPixelRatio(software ? 1 : Math.min(window.devicePixelRatio, 2));
renderer.setClearColor(0x303030);
view.appendChild(renderer.domElement);
const labels = new CSS2DRenderer();
labels.domElement.style.position = "absolute";
labels.domElement.style.top = "0";
labels.domElement.style.pointerEvents = "none";
view.appendChild(labels.domElement);
const scene = new THREE.Scene();
scene.add(new THREE.AmbientLight(0xffffff, 1.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.6);
sun.position.set(3, 2, 6);
scene.add(sun);
const camera = new THREE.PerspectiveCamera(60, 1, 0.01, 2000);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = false;

function setView(v) {
  // rviz's Orbit view: the eye at `distance` from the focal point, at `pitch` above the xy
  // plane, turned `yaw` about z.
  const d = v.distance ?? 10, pitch = v.pitch ?? 0.785398, yaw = v.yaw ?? 0.785398;
  const f = v.focal ?? [0, 0, 0];
  controls.target.set(f[0], f[1], f[2]);
  camera.position.set(
    f[0] + d * Math.cos(pitch) * Math.cos(yaw),
    f[1] + d * Math.cos(pitch) * Math.sin(yaw),
    f[2] + d * Math.sin(pitch));
  controls.update();
  state.dirty = true;
}

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h);
  labels.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener("resize", resize);
resize();

// --- state
const state = {
  fixed: "", frames: new Map(), // name -> {parent, p, q} or {error}
  config: null, displays: new Map(), // id -> Display
  early: new Map(), // id -> the newest [header, data] that came before its display
  meshes: new Map(), // a robot model's mesh URI -> "loading", "loaded" or "failed"
  viewSet: false, connected: false,
  dirty: true, tfVersion: 0, renders: 0, fps: 0, latencies: [], arrivals: [], drawMs: [], pendingStamps: [], unacked: 0,
};

setView({});

function color3(rgb) { return new THREE.Color(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255); }
function optionColor(text, fallback) {
  if (typeof text !== "string") return color3(fallback);
  const parts = text.split(";").map(Number);
  return parts.length === 3 && parts.every(Number.isFinite) ? color3(parts) : color3(fallback);
}
function setPose(obj, pose) {
  obj.position.set(pose.p[0], pose.p[1], pose.p[2]);
  obj.quaternion.set(pose.q[0], pose.q[1], pose.q[2], pose.q[3]);
}
// Where a frame is in the fixed frame, or null (not known to tf, or not connected to it).
function frameOf(name) {
  if (!name || name === state.fixed) return { p: [0, 0, 0], q: [0, 0, 0, 1] };
  const f = state.frames.get(name.replace(/^\//, ""));
  return f && f.p ? f : null;
}
function place(obj, frame) {
  const pose = frameOf(frame);
  obj.visible = pose !== null;
  if (pose) setPose(obj, pose);
  return pose !== null;
}
function disposeTree(obj) {
  obj.traverse((o) => {
    if (o.geometry) o.geometry.dispose();
    if (o.material) [].concat(o.material).forEach((m) => { if (m.map) m.map.dispose(); m.dispose(); });
    if (o.element) o.element.remove();
  });
}
function label(text) {
  const div = document.createElement("div");
  div.className = "label";
  div.textContent = text;
  return new CSS2DObject(div);
}
// A frame's axes as rviz draws them: x red, y green, z blue, solid rods.
const AXIS_COLORS = [0xff0000, 0x00ff00, 0x0000ff];
function axesRods(length, radius = length / 20) {
  const group = new THREE.Group();
  AXIS_COLORS.forEach((color, i) => {
    const rod = new THREE.Mesh(new THREE.CylinderGeometry(radius, radius, length, 12),
      new THREE.MeshBasicMaterial({ color }));
    // three's cylinder stands on y, centred: lay it along axis i, from 0 to length
    if (i === 0) rod.rotation.z = -Math.PI / 2;
    if (i === 2) rod.rotation.x = Math.PI / 2;
    rod.position.setComponent(i, length / 2);
    group.add(rod);
  });
  return group;
}
function arrow(length, color, headLength = 0.3 * length, headWidth = 0.1 * length) {
  const a = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), length,
    color, headLength, headWidth);
  return a;
}

// --- displays: each keeps a root group in the scene and draws its newest data
class Display {
  constructor(info) {
    this.info = info;
    this.root = new THREE.Group();
    this.root.name = `${info.kind}:${info.name}`;
    scene.add(this.root);
    this.frame = "";
    this.missing = null; // the frame this display cannot place
    this.received = 0; // data payloads drawn
  }
  get options() { return this.info.options || {}; }
  setInfo(info) { this.info = info; this.root.visible = info.enabled; }
  clear() { for (const c of [...this.root.children]) { this.root.remove(c); disposeTree(c); } }
  take(_header, _blob) {}
  // Each animation frame: put what was drawn where its frame is now.
  update() {
    if (this.frame === null) return;
    const ok = place(this.root, this.frame);
    this.missing = ok ? null : this.frame;
    if (!this.info.enabled) this.root.visible = false;
  }
  describe() {
    const list = [];
    this.root.traverse((o) => {
      if (o.userData.what) {
        const p = new THREE.Vector3();
        o.getWorldPosition(p);
        list.push({ display: this.info.name, kind: this.info.kind, what: o.userData.what,
          visible: o.visible && this.root.visible, position: [p.x, p.y, p.z] });
      }
    });
    return list;
  }
}

class Grid extends Display {
  constructor(info) {
    super(info);
    this.frame = null;
    const count = Number(this.options["Plane Cell Count"] ?? 10);
    const size = Number(this.options["Cell Size"] ?? 1);
    const grid = new THREE.GridHelper(count * size, count, optionColor(this.options.Color, [160, 160, 164]),
      optionColor(this.options.Color, [160, 160, 164]));
    grid.rotation.x = Math.PI / 2;
    const offset = this.options.Offset || {};
    grid.position.set(Number(offset.X ?? 0), Number(offset.Y ?? 0), Number(offset.Z ?? 0));
    grid.material.transparent = true;
    grid.material.opacity = Number(this.options.Alpha ?? 0.5);
    grid.userData.what = `grid ${count}x${count} cells of ${size} m`;
    this.root.add(grid);
  }
}

class Axes extends Display {
  constructor(info) {
    super(info);
    this.frame = null;
    const axes = axesRods(Number(this.options.Length ?? 1));
    axes.userData.what = "axes";
    this.root.add(axes);
  }
}

// TF: each frame's axes and name, and a line from each frame to its parent.
class TF extends Display {
  constructor(info) {
    super(info);
    this.frame = null;
    this.items = new Map();
    const geometry = new THREE.BufferGeometry();
    this.links = new THREE.LineSegments(geometry,
      new THREE.LineBasicMaterial({ vertexColors: true }));
    this.links.frustumCulled = false;
    this.root.add(this.links);
  }
  update() {
    if (!this.info.enabled) { this.root.visible = false; return; }
    if (this.root.visible && this.seen === state.tfVersion) return; // no new poses
    this.seen = state.tfVersion;
    this.root.visible = true;
    const showNames = this.options["Show Names"] !== false;
    const showArrows = this.options["Show Arrows"] !== false;
    const names = new Set(state.frames.keys()); // the fixed frame too, when tf knows it
    for (const [name, item] of this.items) {
      if (!names.has(name)) { this.root.remove(item); disposeTree(item); this.items.delete(name); }
    }
    const points = [], colors = [];
    for (const name of names) {
      let item = this.items.get(name);
      if (!item) {
        item = new THREE.Group();
        item.userData.what = `frame ${name}`;
        item.add(axesRods(0.5 * Number(this.options["Marker Scale"] ?? 1)));
        const text = label(name);
        text.position.set(0, 0, 0.12);
        item.add(text);
        item.userData.label = text;
        this.items.set(name, item);
        this.root.add(item);
      }
      item.userData.label.visible = showNames;
      const pose = frameOf(name);
      item.visible = pose !== null;
      if (!pose) continue;
      setPose(item, pose);
      const parent = state.frames.get(name)?.parent;
      const parentPose = parent ? frameOf(parent) : null;
      if (showArrows && parentPose) {
        points.push(...pose.p, ...parentPose.p);
        colors.push(1, 1, 0, 1, 0, 1); // yellow at the child, magenta at the parent, as rviz
      }
    }
    this.links.geometry.setAttribute("position", new THREE.Float32BufferAttribute(points, 3));
    this.links.geometry.setAttribute("color", new THREE.Float32BufferAttribute(colors, 3));
  }
}

const stlLoader = new STLLoader();
const colladaLoader = new ColladaLoader();

function material(rgba) {
  return new THREE.MeshStandardMaterial({ color: new THREE.Color(rgba[0], rgba[1], rgba[2]),
    transparent: rgba[3] < 1, opacity: rgba[3], roughness: 0.6, metalness: 0.1 });
}

// RobotModel: each link's visuals, the link placed at its tf frame.
class RobotModel extends Display {
  constructor(info) { super(info); this.frame = null; this.links = new Map(); }
  take(h) {
    if (h.clear) { this.clear(); this.links.clear(); return; }
    this.clear();
    this.links.clear();
    for (const link of h.links) {
      const group = new THREE.Group();
      group.userData.what = `link ${link.name}`;
      for (const v of link.visuals) group.add(this.visual(v, link.name));
      this.links.set(link.name, group);
      this.root.add(group);
    }
  }
  visual(v, link) {
    // The display's Alpha scales every visual's own.
    const alpha = Number(this.options.Alpha ?? 1);
    v = { ...v, color: [v.color[0], v.color[1], v.color[2], v.color[3] * alpha] };
    const holder = new THREE.Group();
    holder.position.set(...v.xyz);
    holder.rotation.copy(new THREE.Euler(v.rpy[0], v.rpy[1], v.rpy[2], "ZYX"));
    let mesh = null;
    if (v.type === "box") mesh = new THREE.Mesh(new THREE.BoxGeometry(...v.size), material(v.color));
    else if (v.type === "sphere") mesh = new THREE.Mesh(new THREE.SphereGeometry(v.radius, 32, 16), material(v.color));
    else if (v.type === "cylinder") {
      mesh = new THREE.Mesh(new THREE.CylinderGeometry(v.radius, v.radius, v.length, 32), material(v.color));
      mesh.rotation.x = Math.PI / 2; // three's cylinders stand on y, URDF's on z
    } else if (v.type === "mesh") {
      holder.scale.set(...v.scale);
      const url = `mesh/${this.info.id}/${v.mesh}`;
      state.meshes.set(v.uri, "loading");
      const loaded = () => { state.meshes.set(v.uri, "loaded"); state.dirty = true; };
      if (v.format === "stl") {
        stlLoader.load(url, (geometry) => {
          geometry.computeVertexNormals();
          holder.add(new THREE.Mesh(geometry, material(v.color)));
          loaded();
        }, undefined, () => this.meshFailed(v.uri));
      } else {
        colladaLoader.load(url, (collada) => {
          collada.scene.quaternion.identity(); // URDF meshes are in the link's frame, z up
          holder.add(collada.scene);
          loaded();
        }, undefined, () => this.meshFailed(v.uri));
      }
    }
    if (mesh) holder.add(mesh);
    holder.userData.what = `${v.type} of ${link}`;
    return holder;
  }
  meshFailed(uri) {
    state.meshes.set(uri, "failed");
    this.meshError = `cannot load mesh ${uri}`;
    renderPanel();
  }
  update() {
    this.root.visible = this.info.enabled;
    const missing = [];
    for (const [name, group] of this.links) {
      if (!place(group, name)) missing.push(name);
    }
    this.missing = missing.length ? missing.join(", ") : null;
  }
}

// Points: LaserScan and PointCloud2, positions (and colours) from the binary frame.
class Cloud extends Display {
  constructor(info) {
    super(info);
    const size = Number(this.options["Size (m)"] ?? (info.kind === "LaserScan" ? 0.05 : 0.03));
    this.material = new THREE.PointsMaterial({ size, sizeAttenuation: true,
      color: info.kind === "LaserScan" ? 0xff3030 : 0xffffff });
    this.points = new THREE.Points(new THREE.BufferGeometry(), this.material);
    this.points.frustumCulled = false;
    this.root.add(this.points);
  }
  take(h, blob) {
    if (h.clear) { this.points.geometry.setDrawRange(0, 0); return; }
    this.frame = h.frame;
    const n = h.count;
    const positions = new Float32Array(blob, 0, n * 3);
    const geometry = this.points.geometry;
    geometry.setAttribute("position", new THREE.BufferAttribute(positions, 3));
    if (h.colors) {
      const rgb = new Uint8Array(blob, n * 12, n * 3);
      geometry.setAttribute("color", new THREE.BufferAttribute(rgb, 3, true));
      this.material.vertexColors = true;
      this.material.color.set(0xffffff);
    } else if (this.material.vertexColors) {
      geometry.deleteAttribute("color");
      this.material.vertexColors = false;
    }
    this.material.needsUpdate = true;
    geometry.setDrawRange(0, n);
    this.points.userData.what = `${n} points` + (h.total > n ? ` of ${h.total}` : "");
  }
}

class Poses extends Display {
  take(h) {
    this.clear();
    if (h.clear) return;
    this.frame = h.frame;
    const single = this.info.kind === "Pose";
    for (const pose of h.poses) {
      const a = arrow(single ? 1 : 0.3, 0xff1900);
      setPose(a, pose);
      a.userData.what = `pose ${pose.p.map((v) => v.toFixed(2)).join(" ")}`;
      this.root.add(a);
    }
  }
}

class PathDisplay extends Display {
  take(h) {
    this.clear();
    if (h.clear) return;
    this.frame = h.frame;
    const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(
      h.points.map((p) => new THREE.Vector3(...p))), new THREE.LineBasicMaterial({ color: 0x19ff00 }));
    line.userData.what = `path of ${h.points.length} poses`;
    this.root.add(line);
  }
}

// Odometry: an arrow per pose, the last 100 that moved at least 0.1 m or 0.1 rad (rviz's
// defaults).
class OdometryDisplay extends Display {
  constructor(info) { super(info); this.kept = []; }
  take(h) {
    if (h.clear) { this.clear(); this.kept = []; return; }
    if (this.frame !== h.frame) { this.clear(); this.kept = []; }
    this.frame = h.frame;
    const pose = h.poses[0];
    const last = this.kept[this.kept.length - 1];
    if (last) {
      const d = Math.hypot(...pose.p.map((v, i) => v - last.userData.pose.p[i]));
      const dq = Math.abs(pose.q.reduce((s, v, i) => s + v * last.userData.pose.q[i], 0));
      if (d < 0.1 && 2 * Math.acos(Math.min(1, dq)) < 0.1) return;
    }
    const a = arrow(1, 0xff1900);
    setPose(a, pose);
    a.userData.pose = pose;
    a.userData.what = `odometry ${pose.p.map((v) => v.toFixed(2)).join(" ")}`;
    this.kept.push(a);
    this.root.add(a);
    while (this.kept.length > 100) { const old = this.kept.shift(); this.root.remove(old); disposeTree(old); }
  }
}

class MapDisplay extends Display {
  take(h, blob) {
    this.clear();
    if (h.clear) return;
    this.frame = h.frame;
    const cells = new Uint8Array(blob);
    const rgba = new Uint8Array(h.width * h.height * 4);
    for (let i = 0; i < cells.length; i++) {
      const v = cells[i];
      let r, g, b;
      if (v === 255) { r = 112; g = 137; b = 134; } // unknown
      else { const k = Math.round(255 - Math.min(v, 100) * 2.55); r = g = b = k; }
      rgba.set([r, g, b, 255], i * 4);
    }
    const texture = new THREE.DataTexture(rgba, h.width, h.height);
    texture.magFilter = THREE.NearestFilter;
    texture.needsUpdate = true;
    const w = h.width * h.resolution, d = h.height * h.resolution;
    const plane = new THREE.Mesh(new THREE.PlaneGeometry(w, d), new THREE.MeshBasicMaterial({
      map: texture, transparent: true, opacity: Number(this.options.Alpha ?? 0.7), side: THREE.DoubleSide }));
    plane.position.set(w / 2, d / 2, 0);
    const holder = new THREE.Group();
    setPose(holder, h.origin);
    holder.add(plane);
    holder.userData.what = `map ${h.total[0]}x${h.total[1]} cells`;
    this.root.add(holder);
  }
}

class ImageDisplay extends Display {
  constructor(info) {
    super(info);
    this.frame = null;
    this.figure = document.createElement("figure");
    this.canvas = document.createElement("canvas");
    const caption = document.createElement("figcaption");
    caption.textContent = `${info.name} ${info.topic}`;
    this.figure.append(caption, this.canvas);
    $("images").appendChild(this.figure);
    this.marker = new THREE.Object3D();
    this.root.add(this.marker);
  }
  take(h, blob) {
    if (h.clear) { this.canvas.width = 0; return; }
    this.canvas.width = h.width;
    this.canvas.height = h.height;
    const pixels = new ImageData(new Uint8ClampedArray(blob), h.width, h.height);
    this.canvas.getContext("2d").putImageData(pixels, 0, 0);
    this.marker.userData.what = `image ${h.total[0]}x${h.total[1]}`;
  }
  update() { this.figure.style.display = this.info.enabled ? "" : "none"; }
}

// Marker and MarkerArray: every marker kept by the server, each placed at its own frame.
const MARKER = { ARROW: 0, CUBE: 1, SPHERE: 2, CYLINDER: 3, LINE_STRIP: 4, LINE_LIST: 5,
  CUBE_LIST: 6, SPHERE_LIST: 7, POINTS: 8, TEXT_VIEW_FACING: 9, MESH_RESOURCE: 10,
  TRIANGLE_LIST: 11 };
const MARKER_NAMES = Object.fromEntries(Object.entries(MARKER).map(([k, v]) => [v, k]));

function markerObject(m) {
  const c = new THREE.Color(m.color[0], m.color[1], m.color[2]);
  const mat = () => new THREE.MeshStandardMaterial({ color: c, transparent: m.color[3] < 1,
    opacity: m.color[3], roughness: 0.6 });
  const s = m.scale;
  const pts = (m.points || []).map((p) => new THREE.Vector3(...p));
  const vertexColors = m.colors && m.colors.length === pts.length;
  const colorArray = vertexColors ? m.colors.flatMap((k) => [k[0], k[1], k[2]]) : null;
  const group = new THREE.Group();
  setPose(group, m.pose);
  let obj;
  switch (m.type) {
    case MARKER.ARROW:
      if (pts.length >= 2) {
        const dir = pts[1].clone().sub(pts[0]);
        obj = new THREE.ArrowHelper(dir.clone().normalize(), pts[0], dir.length(), c,
          s.z > 0 ? s.z : 0.23 * dir.length(), s.y > 0 ? s.y : 0.1 * dir.length());
      } else {
        obj = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), s[0], c,
          0.23 * s[0], Math.max(s[1], s[2]) * 2);
      }
      break;
    case MARKER.CUBE: obj = new THREE.Mesh(new THREE.BoxGeometry(s[0], s[1], s[2]), mat()); break;
    case MARKER.SPHERE:
      obj = new THREE.Mesh(new THREE.SphereGeometry(0.5, 24, 12), mat());
      obj.scale.set(s[0], s[1], s[2]);
      break;
    case MARKER.CYLINDER:
      obj = new THREE.Mesh(new THREE.CylinderGeometry(0.5, 0.5, 1, 24), mat());
      obj.rotation.x = Math.PI / 2;
      obj.scale.set(s[0], s[2], s[1]);
      break;
    case MARKER.LINE_STRIP: case MARKER.LINE_LIST: {
      const g = new THREE.BufferGeometry().setFromPoints(pts);
      if (colorArray) g.setAttribute("color", new THREE.Float32BufferAttribute(colorArray, 3));
      const lm = new THREE.LineBasicMaterial({ color: colorArray ? 0xffffff : c, vertexColors: !!colorArray });
      obj = m.type === MARKER.LINE_STRIP ? new THREE.Line(g, lm) : new THREE.LineSegments(g, lm);
      break;
    }
    case MARKER.POINTS: {
      const g = new THREE.BufferGeometry().setFromPoints(pts);
      if (colorArray) g.setAttribute("color", new THREE.Float32BufferAttribute(colorArray, 3));
      obj = new THREE.Points(g, new THREE.PointsMaterial({ size: s[0] || 0.05,
        color: colorArray ? 0xffffff : c, vertexColors: !!colorArray }));
      break;
    }
    case MARKER.CUBE_LIST: case MARKER.SPHERE_LIST: {
      const geometry = m.type === MARKER.CUBE_LIST ? new THREE.BoxGeometry(s[0], s[1], s[2])
        : new THREE.SphereGeometry(0.5, 12, 8).scale(s[0], s[1], s[2]);
      obj = new THREE.InstancedMesh(geometry, mat(), Math.max(pts.length, 1));
      const matrix = new THREE.Matrix4();
      pts.forEach((p, i) => {
        obj.setMatrixAt(i, matrix.makeTranslation(p.x, p.y, p.z));
        if (colorArray) obj.setColorAt(i, new THREE.Color(...m.colors[i]));
      });
      obj.count = pts.length;
      break;
    }
    case MARKER.TEXT_VIEW_FACING: {
      obj = label(m.text || "");
      obj.element.style.fontSize = `${Math.max(8, Math.min(64, 40 * (s[2] || 0.3)))}px`;
      obj.element.style.color = `#${c.getHexString()}`;
      break;
    }
    case MARKER.TRIANGLE_LIST: {
      const g = new THREE.BufferGeometry().setFromPoints(pts);
      g.computeVertexNormals();
      if (colorArray) g.setAttribute("color", new THREE.Float32BufferAttribute(colorArray, 3));
      const tm = mat();
      tm.side = THREE.DoubleSide;
      tm.vertexColors = !!colorArray;
      obj = new THREE.Mesh(g, tm);
      obj.scale.set(s[0] || 1, s[1] || 1, s[2] || 1);
      break;
    }
    default: // MESH_RESOURCE: a box of its scale stands in
      obj = new THREE.Mesh(new THREE.BoxGeometry(s[0], s[1], s[2]), mat());
  }
  group.add(obj);
  group.userData.what = `marker ${m.ns}/${m.id} ${MARKER_NAMES[m.type] || m.type}`;
  return group;
}

class Markers extends Display {
  constructor(info) { super(info); this.frame = null; this.items = new Map(); }
  take(h) {
    if (h.clear) { this.clear(); this.items.clear(); return; }
    const seen = new Set();
    for (const m of h.markers) {
      const key = `${m.ns}\u0000${m.id}`;
      seen.add(key);
      const text = JSON.stringify([m.type, m.pose, m.scale, m.color, m.points, m.colors, m.text]);
      const old = this.items.get(key);
      if (old && old.text === text) { old.frame = m.frame; continue; }
      if (old) { this.root.remove(old.obj); disposeTree(old.obj); }
      const obj = new THREE.Group();
      obj.add(markerObject(m));
      this.root.add(obj);
      this.items.set(key, { text, obj, frame: m.frame });
    }
    for (const [key, item] of this.items) {
      if (!seen.has(key)) { this.root.remove(item.obj); disposeTree(item.obj); this.items.delete(key); }
    }
  }
  update() {
    this.root.visible = this.info.enabled;
    const missing = new Set();
    for (const item of this.items.values()) if (!place(item.obj, item.frame)) missing.add(item.frame);
    this.missing = missing.size ? [...missing].join(", ") : null;
  }
}

const KINDS = { Grid, Axes, TF, RobotModel, Marker: Markers, MarkerArray: Markers,
  LaserScan: Cloud, PointCloud2: Cloud, Pose: Poses, PoseArray: Poses, Path: PathDisplay,
  Odometry: OdometryDisplay, Map: MapDisplay, Image: ImageDisplay };

// --- the side panel
function li(html, cls) { const e = document.createElement("li"); if (cls) e.className = cls; e.innerHTML = html; return e; }
function esc(text) { return String(text ?? "").replace(/[&<>"]/g, (ch) => `&#${ch.charCodeAt(0)};`); }

function statusOf(d) {
  const info = d.info;
  if (!info.enabled) return ["note", "disabled"];
  if (info.status && info.status.startsWith("error")) return ["error", info.status];
  if (d.meshError) return ["error", d.meshError];
  if (d.missing) return ["warn", `no transform from [${d.missing}] to [${state.fixed}]`];
  if (info.status && info.status !== "ok") return ["warn", info.status];
  const n = d.received;
  return ["ok", n ? `ok · ${n} update${n === 1 ? "" : "s"}` : "ok"];
}

function renderPanel() {
  const list = $("displays");
  list.replaceChildren();
  for (const d of state.displays.values()) {
    const [cls, text] = statusOf(d);
    const item = li(`<label><input type="checkbox" ${d.info.enabled ? "checked" : ""}>
      <span class="kind">${esc(d.info.kind)}</span> ${esc(d.info.name === d.info.kind ? "" : d.info.name)}
      <span class="topic">${esc(d.info.topic || "")}</span></label>
      <span class="status ${cls}">${esc(text)}</span>`);
    item.dataset.display = d.info.id;
    item.dataset.status = text;
    item.querySelector("input").addEventListener("change", (e) =>
      send({ enable: [d.info.id, e.target.checked] }));
    list.appendChild(item);
  }
  const lacking = $("lacking");
  lacking.replaceChildren(...(state.config?.lacking || []).map((line) => li(esc(line), "warn")));
  const topics = $("topics");
  topics.replaceChildren();
  const shown = new Set([...state.displays.values()].map((d) => d.info.topic));
  for (const [topic, type] of Object.entries(state.config?.topics || {})) {
    if (shown.has(topic)) continue;
    const item = li(`<button>Add</button><span class="topic">${esc(topic)}</span> <span class="note">${esc(type)}</span>`);
    item.querySelector("button").addEventListener("click", () => send({ add: topic }));
    topics.appendChild(item);
  }
  if (!topics.children.length) topics.appendChild(li("every such topic is shown", "note"));
}

function renderFrames() {
  const names = [...state.frames.keys()].sort();
  const list = $("frame-names");
  if (list.children.length !== names.length + 1) {
    list.replaceChildren(...[state.fixed, ...names].map((n) => { const o = document.createElement("option"); o.value = n; return o; }));
  }
  $("frames").replaceChildren(...names.slice(0, 200).map((n) => {
    const f = state.frames.get(n);
    return li(`${esc(n)}${f.parent ? ` <span class="note">← ${esc(f.parent)}</span>` : ""}${f.error ? ` <span class="warn">${esc(f.error)}</span>` : ""}`);
  }));
  const fixedKnown = state.frames.has(state.fixed) || [...state.frames.values()].some((f) => f.parent === state.fixed);
  $("fixed-status").textContent = fixedKnown || !state.frames.size ? ""
    : `Frame [${state.fixed}] does not exist`;
  $("fixed-status").className = fixedKnown ? "note" : "warn";
}

const fixedInput = $("fixed");
fixedInput.addEventListener("change", () => send({ fixed: fixedInput.value.trim() }));
fixedInput.addEventListener("focus", () => fixedInput.select()); // typing replaces the frame

// --- the connection
let socket = null;
function send(message) { if (socket && socket.readyState === 1) socket.send(JSON.stringify(message)); }

function onConfig(c) {
  state.config = c;
  state.dirty = true;
  if (state.fixed !== c.fixed) { state.fixed = c.fixed; }
  if (document.activeElement !== fixedInput) fixedInput.value = c.fixed;
  if (!state.viewSet && c.view) { setView(c.view); state.viewSet = true; }
  for (const info of c.displays) {
    const d = state.displays.get(info.id);
    if (d) d.setInfo(info);
    else {
      state.displays.set(info.id, new KINDS[info.kind](info));
      const early = state.early.get(info.id);
      if (early) { state.early.delete(info.id); onDisplay(...early); }
    }
  }
  renderPanel();
}

function onTf(t) {
  state.fixed = t.fixed;
  state.frames = new Map(t.frames.map((f) => [f.name, f]));
  state.tfVersion++;
  state.dirty = true;
  renderFrames();
}

let panelDue = 0;
function onDisplay(h, blob) {
  const d = state.displays.get(h.id);
  if (!d) { state.early.set(h.id, [h, blob]); return; } // before the config that makes it
  d.take(h, blob);
  state.dirty = true;
  if (!h.clear) d.received++;
  if (h.stamp > 0) {
    state.pendingStamps.push(h.stamp);
    state.arrivals.push(Date.now() / 1000 - h.stamp);
    if (state.arrivals.length > 5000) state.arrivals.splice(0, state.arrivals.length - 5000);
  }
  const now = performance.now();
  if (now > panelDue) { panelDue = now + 500; renderPanel(); }
}

function connect() {
  const url = new URL("ws", location.href);
  url.protocol = location.protocol === "https:" ? "wss:" : "ws:";
  url.search = "";
  socket = new WebSocket(url);
  socket.binaryType = "arraybuffer";
  socket.onopen = () => { send({ flow: true }); state.unacked = 0; state.connected = true; $("status").textContent = "live"; $("status").className = ""; };
  socket.onclose = () => {
    state.connected = false;
    $("status").textContent = "disconnected: is rviz2 still running?";
    $("status").className = "down";
    setTimeout(connect, 2000);
  };
  socket.onmessage = (event) => {
    if (typeof event.data === "string") {
      const m = JSON.parse(event.data);
      if (m.type === "config") onConfig(m);
      else if (m.type === "tf") onTf(m);
      else if (m.type === "display" || m.clear) onDisplay(m, null);
      return;
    }
    state.unacked++; // a binary frame: acknowledged once drawn
    const length = new DataView(event.data).getUint32(0);
    const header = JSON.parse(new TextDecoder().decode(new Uint8Array(event.data, 4, length)));
    onDisplay(header, event.data.slice(4 + length));
  };
}
connect();

// --- the animation loop; what the page shows, for tests and benchmarks
// Drawn at most FRAME_RATE times a second (rviz's Frame Rate, 30), and only when something
// changed: the page leaves the CPU to the messages between frames.
const FRAME_RATE = 30;
let fpsCount = 0, fpsSince = performance.now(), lastRender = 0;
controls.addEventListener("change", () => { state.dirty = true; });
window.addEventListener("resize", () => { state.dirty = true; });
function animate(time) {
  requestAnimationFrame(animate);
  if (!state.dirty || time - lastRender < 1000 / FRAME_RATE - 4) return;
  lastRender = time;
  state.dirty = false;
  const started = performance.now();
  for (const d of state.displays.values()) d.update();
  renderer.render(scene, camera);
  labels.render(scene, camera);
  state.drawMs.push(performance.now() - started);
  if (state.drawMs.length > 5000) state.drawMs.splice(0, state.drawMs.length - 5000);
  state.renders++;
  if (state.unacked) { send({ ack: state.unacked }); state.unacked = 0; } // drawn: send more
  const now = performance.now();
  if (state.pendingStamps.length) {
    const wall = Date.now() / 1000;
    for (const stamp of state.pendingStamps) state.latencies.push(wall - stamp);
    state.pendingStamps = [];
    if (state.latencies.length > 5000) state.latencies.splice(0, state.latencies.length - 5000);
  }
  fpsCount++;
  if (now - fpsSince >= 1000) {
    state.fps = (fpsCount * 1000) / (now - fpsSince);
    fpsCount = 0;
    fpsSince = now;
    $("rate").textContent = `${state.fps.toFixed(0)} fps`;
  }
}
requestAnimationFrame(animate);

window.rvizState = {
  get connected() { return state.connected; },
  get fixed() { return state.fixed; },
  get frames() { return [...state.frames.keys()]; },
  get fps() { return state.fps; },
  get renders() { return state.renders; },
  get latencies() { return state.latencies; }, // s from a message's stamp to its drawing
  get arrivals() { return state.arrivals; }, // s from a message's stamp to the page
  get drawMs() { return state.drawMs; }, // ms each frame took to update and draw
  displays() {
    return [...state.displays.values()].map((d) => ({ id: d.info.id, kind: d.info.kind,
      name: d.info.name, topic: d.info.topic, enabled: d.info.enabled, status: statusOf(d)[1] }));
  },
  // Every drawn thing with its place in the fixed frame: what a person sees in the view.
  meshes() { return Object.fromEntries(state.meshes); }, // URI -> loading, loaded, failed
  objects() { return [...state.displays.values()].flatMap((d) => d.describe()); },
  setView,
};
