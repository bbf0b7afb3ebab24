// Index page: reads gallery.json at load time and shows one card per model
// (rendered PNG, title, seed/section, certifying residual lines, links).
// Sets window.cyclideIndex = {models: N} when the cards are built, or
// {error: message} (also logged with console.error) when it cannot.

const status = document.getElementById('status');
const grid = document.getElementById('grid');

function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') e.className = v;
    else e.setAttribute(k, v);
  }
  for (const c of children) e.append(c);
  return e;
}

function card(m) {
  const viewer = 'viewer.html?model=' + encodeURIComponent(m.name);
  const img = el('img', {
    src: 'png/' + encodeURIComponent(m.name) + '.png',
    alt: m.title || m.name,
    width: '640',
    height: '480',
  });
  // Before scripts/gallery has rendered it, say so instead of a broken image.
  img.addEventListener('error', () => {
    img.replaceWith(el('span', { class: 'nopng' }, 'no picture yet (run scripts/gallery)'));
  });
  const meta = [m.seed !== undefined && m.seed !== '' ? 'seed ' + m.seed : null, m.section || null]
    .filter(Boolean).join(' \u00b7 ');
  const residuals = el('pre', { class: 'residuals' });
  residuals.textContent = (m.residuals || []).join('\n');
  const links = el('p', { class: 'links' },
    el('a', { href: viewer }, 'interactive 3D view'), ' \u00b7 ',
    el('a', { href: m.glb, download: '' }, 'glb'));
  for (const x of m.extra || []) {
    links.append(' \u00b7 ', el('a', { href: x }, x.split('/').pop()));
  }
  return el('article', { class: 'card', id: 'model-' + m.name },
    el('a', { href: viewer, class: 'shot' }, img),
    el('h2', {}, m.title || m.name),
    el('p', { class: 'meta' }, meta),
    residuals,
    links);
}

async function main() {
  const res = await fetch('gallery.json', { cache: 'no-store' });
  if (!res.ok) throw new Error(`gallery.json: HTTP ${res.status}`);
  const g = await res.json();
  if (!Array.isArray(g.models)) throw new Error('gallery.json has no "models" array');
  if (g.title) {
    document.title = g.title;
    document.getElementById('title').textContent = g.title;
  }
  if (g.generated) document.getElementById('generated').textContent = 'Generated ' + g.generated;
  for (const m of g.models) grid.append(card(m));
  status.textContent = `${g.models.length} model${g.models.length === 1 ? '' : 's'}.`;
  window.cyclideIndex = { models: g.models.length };
}

main().catch((e) => {
  status.textContent = 'Could not load the gallery: ' + e.message;
  status.classList.add('error');
  window.cyclideIndex = { error: e.message };
  console.error('cyclide gallery:', e);
});
