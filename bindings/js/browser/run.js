// The demo page in headless Chromium (Debian's, driven by puppeteer-core):
// it must sample on load the points Node samples with the same options (same
// count, same bytes: a checksum), draw them, and follow its controls
// (periodic, exact count, an image to stipple). SCREENSHOT=file.png keeps a
// picture of the page.
import assert from 'node:assert/strict';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';
import { poissonDisk } from '../src/index.js';
import { serve } from './server.js';

const ROOT = fileURLToPath(new URL('../../..', import.meta.url));
const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';

function fnv1a(points) {
  const bytes = new Uint8Array(points.buffer, points.byteOffset, points.byteLength);
  let h = 0x811c9dc5;
  for (let i = 0; i < bytes.length; ++i) h = Math.imul(h ^ bytes[i], 0x01000193) >>> 0;
  return h.toString(16).padStart(8, '0');
}

// A 24-bit BMP, black on the left half, white on the right.
function halfBlackBmp(w, h) {
  const row = Math.ceil((3 * w) / 4) * 4;
  const buf = Buffer.alloc(54 + row * h);
  buf.write('BM', 0, 'ascii');
  buf.writeUInt32LE(buf.length, 2);
  buf.writeUInt32LE(54, 10);
  buf.writeUInt32LE(40, 14);
  buf.writeInt32LE(w, 18);
  buf.writeInt32LE(h, 22);
  buf.writeUInt16LE(1, 26);
  buf.writeUInt16LE(24, 28);
  buf.writeUInt32LE(row * h, 34);
  for (let y = 0; y < h; ++y) {
    for (let x = 0; x < w; ++x) buf.fill(x < w / 2 ? 0 : 255, 54 + y * row + 3 * x, 54 + y * row + 3 * x + 3);
  }
  return buf;
}

async function waitDone(page) {
  await page.waitForFunction(() => ['done', 'error'].includes(document.body.dataset.state), { timeout: 120000 });
  const state = await page.evaluate(() => ({
    state: document.body.dataset.state,
    count: Number(document.body.dataset.count),
    checksum: document.body.dataset.checksum,
    shown: document.getElementById('count-out').textContent,
    error: document.getElementById('error').textContent,
  }));
  assert.equal(state.state, 'done', `the page reports: ${state.error}`);
  return state;
}

// Dark pixels of a canvas (a pattern drawn, a spectrum shown).
async function darkPixels(page, id) {
  return page.evaluate((canvasId) => {
    const c = document.getElementById(canvasId);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 128) ++n;
    return n;
  }, id);
}

async function submit(page, settings) {
  await page.evaluate((s) => {
    for (const [id, value] of Object.entries(s)) {
      const el = document.getElementById(id);
      if (el.type === 'checkbox') el.checked = value; else el.value = value;
    }
    document.body.dataset.state = 'submitted';
    document.getElementById('go').click();
  }, settings);
  return waitDone(page);
}

const profile = mkdtempSync(join(tmpdir(), 'poissondisk-chromium-'));
const { server, url } = await serve(ROOT);
const browser = await puppeteer.launch({
  executablePath: CHROMIUM,
  headless: true,
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--disable-component-update', '--disable-sync', '--no-first-run', `--user-data-dir=${profile}`],
});
try {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.setViewport({ width: 1100, height: 900 });
  await page.goto(`${url}/docs/demo/index.html`);

  // On load: radius 0.01, seed 1, the unit square.
  const first = await waitDone(page);
  const expected = await poissonDisk(0.01, { seed: 1 });
  assert.equal(first.count, expected.length / 2);
  assert.equal(first.shown, `${expected.length / 2} points`);
  assert.equal(first.checksum, fnv1a(expected), 'the browser samples the bytes Node samples');
  const dots = await darkPixels(page, 'pattern');
  assert.ok(dots > first.count, `the pattern is drawn (${dots} dark pixels)`);
  assert.ok(await darkPixels(page, 'spectrum') > 100, 'the spectrum is drawn');
  if (process.env.SCREENSHOT) await page.screenshot({ path: process.env.SCREENSHOT });

  // Periodic, exact count, another seed: 2x2 tiles, so four times the dots.
  const torus = await submit(page, { periodic: true, count: '1500', seed: '42' });
  assert.equal(torus.count, 1500);
  assert.equal(torus.checksum, fnv1a(await poissonDisk(null, { seed: 42, periodic: true, count: 1500 })));
  assert.ok(await darkPixels(page, 'pattern') > 4 * 1500, 'four tiles are drawn');
  if (process.env.SCREENSHOT) await page.screenshot({ path: process.env.SCREENSHOT.replace(/\.png$/, '-torus.png') });

  // Stippling: a half-black image gives the left half the smaller radius.
  await submit(page, { periodic: false, count: '', seed: '1', rmin: '0.005', rmax: '0.02' });
  const bmp = join(profile, 'half.bmp');
  writeFileSync(bmp, halfBlackBmp(64, 64));
  await page.evaluate(() => { document.body.dataset.state = 'submitted'; });
  const input = await page.$('#image');
  await input.uploadFile(bmp);
  const stipple = await waitDone(page);
  const [left, right] = await page.evaluate(() => {
    const { points } = window.lastPattern;
    const sums = [0, 0];
    for (let i = 0; i < points.length; i += 2) sums[points[i] < 0.5 ? 0 : 1] += 1;
    return sums;
  });
  assert.ok(left > 3 * right, `denser where the image is dark (${left} vs ${right} points)`);
  assert.ok(stipple.count > 3000);
  if (process.env.SCREENSHOT) await page.screenshot({ path: process.env.SCREENSHOT.replace(/\.png$/, '-stipple.png') });
  assert.deepEqual(errors, [], 'no errors on the page');
  console.log(`browser: ok (on load ${first.count} points, as Node; torus 1500; stipple ${stipple.count})`);
} finally {
  await browser.close();
  server.close();
  rmSync(profile, { recursive: true, force: true });
}
