// Renders OUT_DIR/png/<name>.png for every model of OUT_DIR/gallery.json:
// serves OUT_DIR on a free loopback port, opens viewer.html?model=<name>&shot
// in headless Chromium at WIDTHxHEIGHT, waits for the viewer to report the
// model loaded, checks the frame is not blank and screenshots the canvas.
// Exits non-zero if any model fails (console error, failed request, load
// error, blank frame). Usage: node render.mjs OUT_DIR [--size 640x480]
import fs from 'node:fs';
import path from 'node:path';
import { startServer } from './server.mjs';
import { launch, watchPage } from './browser.mjs';

const args = process.argv.slice(2);
let out = null, width = 640, height = 480;
for (let i = 0; i < args.length; i++) {
  if (args[i] === '--size') [width, height] = args[++i].split('x').map(Number);
  else out = args[i];
}
if (!out) {
  console.error('usage: node render.mjs OUT_DIR [--size WxH]');
  process.exit(2);
}
const gallery = JSON.parse(fs.readFileSync(path.join(out, 'gallery.json'), 'utf8'));
const models = gallery.models || [];
for (const m of models) {
  if (!/^[A-Za-z0-9][A-Za-z0-9._-]*$/.test(m.name || '')) {
    console.error(`gallery.json: model name "${m.name}" is not file-safe`);
    process.exit(1);
  }
}
fs.mkdirSync(path.join(out, 'png'), { recursive: true });

const server = await startServer(out);
const browser = await launch();
let failed = 0;
try {
  const context = await browser.newContext({ viewport: { width, height }, deviceScaleFactor: 1 });
  const one = async (m) => {
    const problems = [];
    const page = await context.newPage();
    watchPage(page, problems, m.name);
    const t0 = Date.now();
    try {
      await page.goto(`${server.url}viewer.html?model=${encodeURIComponent(m.name)}&shot`);
      await page.waitForFunction(() => window.cyclideLoaded, null, { timeout: 30000 });
      const loaded = await page.evaluate(() => window.cyclideLoaded);
      if (loaded.error) problems.push(`${m.name}: ${loaded.error}`);
      const stats = await page.evaluate(() => window.cyclideCanvasStats());
      if (!loaded.error && stats.nonBackground === 0) problems.push(`${m.name}: blank frame`);
      const png = path.join(out, 'png', `${m.name}.png`);
      if (problems.length === 0) {
        await page.locator('canvas').screenshot({ path: png });
        console.log(`gallery: ${png} (${loaded.triangles} triangles, ` +
          `${stats.nonBackground} of ${stats.width * stats.height} pixels drawn, ${Date.now() - t0} ms)`);
      }
    } catch (e) {
      problems.push(`${m.name}: ${e.message.split('\n')[0]}`);
    }
    await page.close();
    if (problems.length) {
      failed++;
      for (const p of problems) console.error('gallery: FAILED ' + p);
    }
  };
  // A few pages at once (SwiftShader renders on the CPU; default 2 jobs).
  const jobs = Math.max(1, Number(process.env.CYCLIDE_GALLERY_JOBS) || 2);
  let next = 0;
  await Promise.all(Array.from({ length: Math.min(jobs, models.length) }, async () => {
    while (next < models.length) await one(models[next++]);
  }));
} finally {
  await browser.close();
  await server.close();
}
if (failed) {
  console.error(`gallery: ${failed} of ${models.length} models failed to render`);
  process.exit(1);
}
console.log(`gallery: rendered ${models.length} models into ${path.join(out, 'png')}`);
