// Drives Debian's chromium over a page `twinraster compare --html` wrote, as a user would:
// loads it from file://, moves the split slider, switches to the heat map, hovers a pixel and
// checks the readout against `twinraster trace --json` at that pixel and against metrics.json,
// opens a buffer row, and fails on any console error. Writes a screenshot.
//
//   node check_compare_page.mjs PAGE_DIR TRACE_JSON SCREENSHOT_PNG
// Exit 0: every check held; 1: a check failed (each printed); 77: playwright-core or chromium
// is missing (the gtest wrapper decides whether that skips or fails).
import fs from 'node:fs';
import path from 'node:path';
import { collectErrors, launchChromium, makeChecks } from './browser_check.mjs';

const [dir, tracePath, screenshot] = process.argv.slice(2);

const metrics = JSON.parse(fs.readFileSync(path.join(dir, 'metrics.json'), 'utf8'));
const trace = JSON.parse(fs.readFileSync(tracePath, 'utf8'));
const { check, exitStatus } = makeChecks();

const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
  const errors = collectErrors(page);
  await page.goto('file://' + path.resolve(dir, 'index.html'));
  await page.waitForSelector('body[data-pixels=ready]', { timeout: 30000 });

  const text = (id) => page.locator('#' + id).textContent();
  async function hover(x, y) {
    await page.locator('#stage').scrollIntoViewIfNeeded();
    const box = await page.locator('#base').boundingBox();
    await page.mouse.move(box.x + (x + 0.5) * box.width / metrics.width, box.y + (y + 0.5) * box.height / metrics.height);
  }

  // The readout at the traced pixel: the CPU's values are the trace's.
  await hover(trace.x, trace.y);
  check(await text('ro-xy') === `(${trace.x}, ${trace.y})`, `readout names pixel (${trace.x}, ${trace.y})`);
  const cpuRgba = await text('ro-cpu-rgba');
  check(cpuRgba === trace.final.rgba.join(' '), `cpu RGBA ${cpuRgba} is the trace's ${trace.final.rgba.join(' ')}`);
  const cpuDepth = await text('ro-cpu-depth');
  check(cpuDepth === String(trace.final.depth), `cpu depth ${cpuDepth} is the trace's ${trace.final.depth}`);
  const cpuTriangle = await text('ro-cpu-triangle');
  const traced = trace.final.triangle === null || trace.final.triangle === undefined ? 'none' : String(trace.final.triangle);
  check(cpuTriangle === traced, `cpu triangle ${cpuTriangle} is the trace's ${traced}`);
  // The difference shown is the largest RGB channel difference of the two RGBA shown.
  const gl = (await text('ro-gl-rgba')).split(' ').map(Number), cpu = cpuRgba.split(' ').map(Number);
  const cls = await text('ro-class');
  const channelDiff = Math.max(...[0, 1, 2].map((c) => Math.abs(cpu[c] - gl[c])));
  const both = !['empty', 'coverage_cpu', 'coverage_gl', 'excluded_line'].includes(cls);
  check(Number(await text('ro-diff')) === (both ? channelDiff : 0), `difference ${await text('ro-diff')} matches the two RGBA (class ${cls})`);

  // The worst pixel: the readout's difference there is metrics.json's max_abs_diff.
  if (metrics.max_abs_diff_at && metrics.max_abs_diff_at.x >= 0) {
    await hover(metrics.max_abs_diff_at.x, metrics.max_abs_diff_at.y);
    check(Number(await text('ro-diff')) === metrics.max_abs_diff, `difference at max_abs_diff_at is max_abs_diff ${metrics.max_abs_diff}`);
  }

  // The split slider clips the CPU image at its value.
  await page.locator('#split').fill('25');
  const clip = await page.locator('#top').evaluate((e) => e.style.clipPath);
  check(clip.includes('75%'), `split at 25 clips the CPU image right of 25% (${clip})`);

  // Zoom 4x: the image is four times the frame, and the readout still names the pixel under the pointer.
  await page.click('button[data-zoom="4"]');
  const zoomed = await page.locator('#base').boundingBox();
  check(Math.round(zoomed.width) === metrics.width * 4, `zoom 4x draws the frame ${metrics.width * 4} px wide (${zoomed.width})`);
  await hover(2, 3);
  check(await text('ro-xy') === '(2, 3)', 'at 4x the readout names the pixel under the pointer');
  await page.click('button[data-zoom="1"]');

  // The heat map, exactly the frame's size.
  await page.click('button[data-mode="heat"]');
  await page.waitForFunction(() => document.getElementById('base').src.endsWith('page_heat.png') && document.getElementById('base').complete);
  const heatWidth = await page.locator('#base').evaluate((e) => e.naturalWidth);
  check(heatWidth === metrics.width, `heat map is ${metrics.width} px wide (${heatWidth})`);
  await page.click('button[data-mode="split"]');

  // A buffer row opens its images.
  const rows = page.locator('#buffers tr.open');
  if (await rows.count() > 0) {
    const row = rows.first();
    await row.click();
    const images = row.locator('xpath=following-sibling::tr[1]');
    check(await images.isVisible(), 'a buffer row opens its images');
    const loaded = await images.locator('img').evaluateAll((list) => Promise.all(list.map((img) =>
      img.complete ? img.naturalWidth : new Promise((done) => { img.onload = () => done(img.naturalWidth); img.onerror = () => done(0); }))));
    check(loaded.length > 0 && loaded.every((w) => w > 0), `its ${loaded.length} images load`);
  }

  // The verdict names what metrics.json says.
  const verdict = await text('verdict');
  const expected = !metrics.thresholds || Object.keys(metrics.thresholds.limits).length === 0 ? 'no targets'
    : metrics.thresholds.passed ? 'within targets' : 'over the targets';
  check(verdict === expected, `verdict "${verdict}" is "${expected}"`);

  await hover(trace.x, trace.y);
  if (screenshot) await page.screenshot({ path: screenshot, fullPage: true });
  check(errors.length === 0, 'no console errors' + (errors.length ? ': ' + errors.join('; ') : ''));
} finally {
  await browser.close();
}
process.exit(exitStatus());
