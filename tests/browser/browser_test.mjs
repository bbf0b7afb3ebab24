// Browser test of the gallery in OUT_DIR (built by scripts/gallery): serves
// OUT_DIR on a loopback port and, in headless Debian Chromium driven by
// playwright-core, opens index.html and viewer.html?model=<name> for every
// model of gallery.json. A page fails on any console error, uncaught page
// error, failed request or HTTP error; the index must show one card per
// model with its residual lines and a non-blank PNG; each viewer must report
// its glb loaded (window.cyclideLoaded without error, triangles > 0, and
// as many distinct part colours as the model's "colours" says), draw
// a non-blank canvas, and move its camera on a mouse drag (OrbitControls)
// and still draw the model. Screenshots go to OUT_DIR/screenshots/.
// Usage: node tests/browser/browser_test.mjs OUT_DIR
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const tools = path.resolve(here, '..', '..', 'web', 'tools');
const { startServer } = await import(path.join(tools, 'server.mjs'));
const { launch, watchPage } = await import(path.join(tools, 'browser.mjs'));

const out = process.argv[2];
if (!out) {
  console.error('usage: node browser_test.mjs OUT_DIR');
  process.exit(2);
}
const gallery = JSON.parse(fs.readFileSync(path.join(out, 'gallery.json'), 'utf8'));
const models = gallery.models || [];
const shots = path.join(out, 'screenshots');
fs.rmSync(shots, { recursive: true, force: true });
fs.mkdirSync(shots, { recursive: true });

let passed = 0, failed = 0;
async function check(label, fn) {
  const problems = [];
  const t0 = Date.now();
  try {
    await fn(problems);
  } catch (e) {
    problems.push(e.message.split('\n')[0]);
  }
  if (problems.length) {
    failed++;
    console.log(`FAIL ${label}`);
    for (const p of problems) console.log(`     ${p}`);
  } else {
    passed++;
    console.log(`ok   ${label} (${Date.now() - t0} ms)`);
  }
}

const server = await startServer(out);
const browser = await launch();
try {
  const context = await browser.newContext({ viewport: { width: 1200, height: 800 }, deviceScaleFactor: 1 });

  await check('index.html shows every model with its picture and residuals', async (problems) => {
    const page = await context.newPage();
    watchPage(page, problems, 'index');
    await page.goto(server.url + 'index.html');
    await page.waitForFunction(() => window.cyclideIndex, null, { timeout: 20000 });
    const idx = await page.evaluate(() => window.cyclideIndex);
    if (idx.error) problems.push(`index: ${idx.error}`);
    if (idx.models !== models.length) problems.push(`index: ${idx.models} cards for ${models.length} models`);
    await page.waitForFunction(() => [...document.images].every((i) => i.complete), null, { timeout: 20000 });
    const cards = await page.evaluate(() => {
      const bg = [243, 243, 239];
      return [...document.querySelectorAll('article.card')].map((c) => {
        const img = c.querySelector('img');
        let drawn = 0;
        if (img && img.naturalWidth > 0) {
          const q = document.createElement('canvas');
          q.width = img.naturalWidth;
          q.height = img.naturalHeight;
          const ctx = q.getContext('2d', { willReadFrequently: true });
          ctx.drawImage(img, 0, 0);
          const d = ctx.getImageData(0, 0, q.width, q.height).data;
          for (let i = 0; i < d.length; i += 4) {
            if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 24) drawn++;
          }
        }
        return {
          id: c.id,
          width: img ? img.naturalWidth : 0,
          drawn,
          residuals: c.querySelector('.residuals')?.textContent ?? null,
          viewer: c.querySelector('a[href^="viewer.html?model="]')?.getAttribute('href') ?? null,
        };
      });
    });
    for (const m of models) {
      const c = cards.find((x) => x.id === 'model-' + m.name);
      if (!c) { problems.push(`${m.name}: no card`); continue; }
      if (c.width === 0) problems.push(`${m.name}: PNG did not load`);
      else if (c.drawn === 0) problems.push(`${m.name}: PNG is blank`);
      if (c.residuals !== (m.residuals || []).join('\n')) problems.push(`${m.name}: residual lines differ from gallery.json`);
      if (c.viewer !== 'viewer.html?model=' + encodeURIComponent(m.name)) problems.push(`${m.name}: no viewer link`);
    }
    await page.screenshot({ path: path.join(shots, 'index.png'), fullPage: true });
    await page.close();
  });

  // A few viewer pages at once (SwiftShader renders on the CPU; default 2).
  const jobs = Math.max(1, Number(process.env.CYCLIDE_GALLERY_JOBS) || 2);
  let next = 0;
  const viewer = (m) =>
    check(`viewer.html?model=${m.name} loads ${m.glb} and draws it`, async (problems) => {
      const page = await context.newPage();
      watchPage(page, problems, m.name);
      await page.goto(`${server.url}viewer.html?model=${encodeURIComponent(m.name)}`);
      await page.waitForFunction(() => window.cyclideLoaded, null, { timeout: 20000 });
      const loaded = await page.evaluate(() => window.cyclideLoaded);
      if (loaded.error) problems.push(`${m.name}: ${loaded.error}`);
      else if (!(loaded.triangles > 0)) problems.push(`${m.name}: no triangles`);
      else if (m.colours !== undefined && loaded.colours !== m.colours) {
        problems.push(`${m.name}: ${loaded.colours} colours drawn, gallery.json says ${m.colours}`);
      }
      const before = await page.evaluate(() => window.cyclideCanvasStats());
      if (before.nonBackground === 0) problems.push(`${m.name}: blank canvas`);
      await page.screenshot({ path: path.join(shots, `viewer-${m.name}.png`) });
      if (!loaded.error) {
        const cam0 = await page.evaluate(() => window.cyclideCamera());
        await page.mouse.move(900, 400);
        await page.mouse.down();
        await page.mouse.move(700, 300, { steps: 4 });
        await page.mouse.up();
        const cam1 = await page.evaluate(() => window.cyclideCamera());
        const after = await page.evaluate(() => window.cyclideCanvasStats());
        if (cam0.every((v, i) => v === cam1[i])) problems.push(`${m.name}: dragging did not rotate the view`);
        if (after.nonBackground === 0) problems.push(`${m.name}: blank canvas after rotating`);
      }
      await page.close();
    });
  await Promise.all(Array.from({ length: Math.min(jobs, models.length) }, async () => {
    while (next < models.length) await viewer(models[next++]);
  }));
} finally {
  await browser.close();
  await server.close();
}
console.log(`screenshots in ${shots}`);
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
