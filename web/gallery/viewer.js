// Interactive view of one gallery model: viewer.html?model=<name>.
// Reads gallery.json, loads the model's glb with three's GLTFLoader, lights
// it, frames the camera on it (see frame) and lets OrbitControls move it.
// `&shot` (used by scripts/gallery to render the PNGs) shows the canvas only.
//
// Colours: each part keeps its glTF material's base colour (cyclide writes
// one material per grid colour: a blend and the shapes it joins differ) or
// its COLOR_0 vertex colours; a primitive without a material is SURFACE.
//
// For the renderer and the browser test it sets
//   window.cyclideLoaded = {name, triangles, vertices, colours, bbox: {min, max}}
// (colours: the distinct colours of the drawn parts)
// after the first frame, or {name, error} (also logged with console.error),
// window.cyclideCanvasStats() -> {width, height, nonBackground} counts the
// canvas pixels that differ from the background colour, and
// window.cyclideCamera() -> [x, y, z] is the camera position.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const BACKGROUND = 0xf3f3ef;
const SURFACE = 0x3f7fb8;

const params = new URLSearchParams(location.search);
const name = params.get('model');
const shot = params.has('shot');
if (shot) document.body.classList.add('shot');

const container = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(shot ? 1 : window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
container.append(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(BACKGROUND);
const camera = new THREE.PerspectiveCamera(35, window.innerWidth / window.innerHeight, 0.01, 100);
scene.add(camera);
scene.add(new THREE.HemisphereLight(0xffffff, 0x556070, 1.4));
const key = new THREE.DirectionalLight(0xffffff, 2.2);
key.position.set(1, 1.5, 2); // relative to the camera: follows the view
camera.add(key);

const controls = new OrbitControls(camera, renderer.domElement);
const render = () => renderer.render(scene, camera);
controls.addEventListener('change', render);

let home = null;
const materials = [];

// Frames the camera on the model: an oblique view direction, the orbit
// target at the middle of the model's silhouette, and the distance at which
// every vertex is inside the frustum (with a small margin).
function frame(object, box, up) {
  const center = box.getCenter(new THREE.Vector3());
  const dir = up === 'z' ? new THREE.Vector3(1.0, -1.4, 0.9) : new THREE.Vector3(1.0, 0.9, 1.4);
  dir.normalize();
  camera.up.set(0, up === 'z' ? 0 : 1, up === 'z' ? 1 : 0);
  camera.position.copy(center).add(dir);
  camera.lookAt(center);
  camera.updateMatrixWorld();
  const X = new THREE.Vector3(), Y = new THREE.Vector3(), Z = new THREE.Vector3();
  camera.matrixWorld.extractBasis(X, Y, Z);
  const points = [];
  const seen = new Set(); // the parts (primitives) of one mesh share its vertices
  object.updateMatrixWorld(true);
  object.traverse((o) => {
    if (!o.isMesh) return;
    const pos = o.geometry.getAttribute('position');
    if (seen.has(pos.array)) return;
    seen.add(pos.array);
    const step = Math.max(1, Math.floor(pos.count / 50000)); // enough to frame
    for (let i = 0; i < pos.count; i += step) {
      points.push(new THREE.Vector3().fromBufferAttribute(pos, i).applyMatrix4(o.matrixWorld).sub(center));
    }
  });
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of points) {
    const x = p.dot(X), y = p.dot(Y);
    x0 = Math.min(x0, x); x1 = Math.max(x1, x);
    y0 = Math.min(y0, y); y1 = Math.max(y1, y);
  }
  const shift = X.clone().multiplyScalar((x0 + x1) / 2).addScaledVector(Y, (y0 + y1) / 2);
  const target = center.clone().add(shift);
  const tanV = Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2);
  const tanH = tanV * camera.aspect;
  let dist = 0;
  for (const p of points) {
    const q = p.clone().sub(shift);
    const z = q.dot(Z);
    dist = Math.max(dist, z + Math.abs(q.dot(X)) / tanH, z + Math.abs(q.dot(Y)) / tanV);
  }
  const radius = Math.max(box.getBoundingSphere(new THREE.Sphere()).radius, 1e-6);
  dist = Math.max(dist * 1.06, radius * 1e-3);
  camera.position.copy(target).addScaledVector(dir, dist);
  camera.near = dist / 100; // room to zoom in and out
  camera.far = (dist + radius) * 20;
  camera.updateProjectionMatrix();
  controls.target.copy(target);
  controls.update();
  home = { position: camera.position.clone(), target: target.clone() };
}

function fail(message) {
  document.getElementById('title').textContent = 'Could not load ' + (name || 'a model');
  document.getElementById('stats').textContent = message;
  document.getElementById('stats').classList.add('error');
  window.cyclideLoaded = { name, error: message };
  console.error('cyclide viewer:', message);
}

async function main() {
  if (!name) throw new Error('no ?model=<name> in the address');
  const res = await fetch('gallery.json', { cache: 'no-store' });
  if (!res.ok) throw new Error(`gallery.json: HTTP ${res.status}`);
  const g = await res.json();
  const m = (g.models || []).find((x) => x.name === name);
  if (!m) throw new Error(`no model named "${name}" in gallery.json`);

  document.title = (m.title || m.name) + ' \u2014 cyclide viewer';
  document.getElementById('title').textContent = m.title || m.name;
  document.getElementById('meta').textContent =
    [m.seed ? 'seed ' + m.seed : null, m.section || null].filter(Boolean).join(' \u00b7 ');
  document.getElementById('residuals').textContent = (m.residuals || []).join('\n');

  // Plain fetch + parse (rather than loadAsync's streamed FileLoader) so a
  // bad address or a bad file is reported as exactly that.
  const glb = await fetch(m.glb, { cache: 'no-store' });
  if (!glb.ok) throw new Error(`${m.glb}: HTTP ${glb.status}`);
  const base = new URL(m.glb, location.href);
  let gltf;
  try {
    gltf = await new GLTFLoader().parseAsync(await glb.arrayBuffer(), new URL('.', base).href);
  } catch (e) {
    throw new Error(`${m.glb} is not a valid glTF binary: ${e && e.message ? e.message : e}`);
  }
  let triangles = 0, vertices = 0;
  const colours = new Set();
  const counted = new Set(); // primitives share one geometry's vertices
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    const geo = o.geometry;
    if (!geo.getAttribute('normal')) geo.computeVertexNormals();
    const pos = geo.getAttribute('position');
    if (!counted.has(pos.array)) {
      counted.add(pos.array);
      vertices += pos.count;
    }
    triangles += (geo.index ? geo.index.count : pos.count) / 3;
    // The file's material (not GLTFLoader's default for primitives without one).
    const own = gltf.parser.associations.has(o.material) ? o.material : null;
    const vertexColors = !!geo.getAttribute('color');
    // Open patches are seen from both sides.
    const mat = new THREE.MeshStandardMaterial({
      color: own ? own.color : vertexColors ? 0xffffff : SURFACE,
      vertexColors,
      opacity: own ? own.opacity : 1,
      transparent: own ? own.transparent : false,
      side: THREE.DoubleSide,
      roughness: 0.5,
      metalness: 0.05,
    });
    colours.add(vertexColors ? 'vertex colours' : mat.color.getHexString() + mat.opacity);
    materials.push(mat);
    o.material = mat;
  });
  if (triangles === 0) throw new Error(`${m.glb} has no triangles`);
  scene.add(gltf.scene);
  const box = new THREE.Box3().setFromObject(gltf.scene);
  if (box.isEmpty()) throw new Error(`${m.glb} has an empty bounding box`);
  frame(gltf.scene, box, m.up);
  render();

  document.getElementById('stats').textContent =
    `${triangles} triangles, ${vertices} vertices, ${colours.size} ` +
    `colour${colours.size === 1 ? '' : 's'}; ` +
    `box [${box.min.toArray().map((v) => v.toPrecision(4)).join(', ')}] \u2013 ` +
    `[${box.max.toArray().map((v) => v.toPrecision(4)).join(', ')}]`;
  window.cyclideLoaded = {
    name, triangles, vertices, colours: colours.size,
    bbox: { min: box.min.toArray(), max: box.max.toArray() },
  };
}

window.cyclideCanvasStats = () => {
  render();
  const c = renderer.domElement;
  const probe = document.createElement('canvas');
  probe.width = c.width;
  probe.height = c.height;
  const ctx = probe.getContext('2d', { willReadFrequently: true });
  ctx.drawImage(c, 0, 0);
  const data = ctx.getImageData(0, 0, c.width, c.height).data;
  // The canvas holds sRGB bytes; BACKGROUND is an sRGB hex.
  const [br, bgc, bb] = [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255];
  let nonBackground = 0;
  for (let i = 0; i < data.length; i += 4) {
    if (Math.abs(data[i] - br) + Math.abs(data[i + 1] - bgc) + Math.abs(data[i + 2] - bb) > 24) {
      nonBackground++;
    }
  }
  return { width: c.width, height: c.height, nonBackground };
};

// Where the camera is (the browser test drags and checks that it moved).
window.cyclideCamera = () => camera.position.toArray();

window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
  render();
});

window.addEventListener('keydown', (e) => {
  if (e.key === 'w' || e.key === 'W') {
    for (const mat of materials) mat.wireframe = !mat.wireframe;
    render();
  } else if ((e.key === 'r' || e.key === 'R') && home) {
    camera.position.copy(home.position);
    controls.target.copy(home.target);
    controls.update();
    render();
  }
});

main().catch((e) => fail(e && e.message ? e.message : String(e)));
