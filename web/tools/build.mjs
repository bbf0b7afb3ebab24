// Copies the gallery's static pages (web/gallery/*) into OUT_DIR and the
// three.js module build into OUT_DIR/lib/three/: build/three.module.js and
// the examples/jsm addons the pages import (GLTFLoader, OrbitControls),
// with every file they import in turn (found by following relative
// `from '...'` specifiers; the bare 'three' maps to the build via the
// pages' import map). Usage: node build.mjs OUT_DIR
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const web = path.resolve(here, '..');
const threeRoot = path.join(web, 'node_modules', 'three');
const ENTRIES = [
  'build/three.module.js',
  'examples/jsm/loaders/GLTFLoader.js',
  'examples/jsm/controls/OrbitControls.js',
];

const out = process.argv[2];
if (!out) {
  console.error('usage: node build.mjs OUT_DIR');
  process.exit(2);
}
if (!fs.existsSync(path.join(threeRoot, 'package.json'))) {
  console.error(`three is not installed in ${web}/node_modules (run npm ci there)`);
  process.exit(1);
}

// Static pages.
const pages = path.join(web, 'gallery');
for (const f of fs.readdirSync(pages)) {
  fs.copyFileSync(path.join(pages, f), path.join(out, f));
}

// three: entries plus their relative imports, transitively.
const libDir = path.join(out, 'lib', 'three');
fs.rmSync(libDir, { recursive: true, force: true });
const seen = new Set();
const queue = [...ENTRIES];
const spec = /^\s*(?:import|export)\s*(?:\{[^}]*\}|\*(?:\s+as\s+\w+)?|\w+(?:\s*,\s*\{[^}]*\})?)\s*from\s*['"]([^'"]+)['"]|^\s*import\s*['"]([^'"]+)['"]/gm;
while (queue.length) {
  const rel = path.normalize(queue.shift());
  if (seen.has(rel)) continue;
  seen.add(rel);
  const src = path.join(threeRoot, rel);
  const text = fs.readFileSync(src, 'utf8');
  fs.mkdirSync(path.dirname(path.join(libDir, rel)), { recursive: true });
  fs.copyFileSync(src, path.join(libDir, rel));
  for (const m of text.matchAll(spec)) {
    const s = m[1] || m[2];
    if (s.startsWith('.')) queue.push(path.join(path.dirname(rel), s));
    else if (s !== 'three') throw new Error(`${rel} imports unmapped module '${s}'`);
  }
}
for (const f of ['LICENSE', 'package.json']) {
  fs.copyFileSync(path.join(threeRoot, f), path.join(libDir, f));
}
const version = JSON.parse(fs.readFileSync(path.join(threeRoot, 'package.json'), 'utf8')).version;
console.log(`gallery: pages and three ${version} (${seen.size} modules) copied to ${out}`);
