// Drives Debian's chromium over the index `twinraster suite` wrote, as a user would: loads it
// from file://, checks a row per scene of suite.json with its verdict and thumbnails, sorts by
// a number column both ways and by name, opens a scene's page from its link, and fails on any
// console error. Writes a screenshot of the index.
//
//   node check_suite_page.mjs SUITE_DIR SCREENSHOT_PNG
// Exit 0: every check held; 1: a check failed (each printed); 77: playwright-core or chromium
// is missing (the gtest wrapper decides whether that skips or fails).
import fs from 'node:fs';
import path from 'node:path';
import { collectErrors, launchChromium, makeChecks } from './browser_check.mjs';

const [dir, screenshot] = process.argv.slice(2);

const suite = JSON.parse(fs.readFileSync(path.join(dir, 'suite.json'), 'utf8'));
const { check, exitStatus } = makeChecks();

const browser = await launchChromium();
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  const errors = collectErrors(page);
  await page.goto('file://' + path.resolve(dir, 'index.html'));

  // A row per scene, in suite.json's order, with its verdict.
  const rows = page.locator('#scenes tbody tr');
  check(await rows.count() === suite.cases.length, `${suite.cases.length} rows, one per scene`);
  const scenes = await rows.evaluateAll((trs) => trs.map((tr) => tr.dataset.scene));
  check(JSON.stringify(scenes) === JSON.stringify(suite.cases.map((c) => c.scene)), 'rows in the order scenes were given');
  const verdicts = await page.locator('#scenes tbody .verdict').allTextContents();
  check(JSON.stringify(verdicts) === JSON.stringify(suite.cases.map((c) => c.outcome)), `verdicts ${verdicts.join(' ')}`);

  // Every thumbnail loads (an error case shows none).
  await page.evaluate(() => Promise.all(Array.from(document.images).map((img) => {
    img.loading = 'eager';
    return img.complete ? null : new Promise((done) => { img.onload = img.onerror = done; });
  })));
  const thumbs = await page.locator('img.thumb').evaluateAll((imgs) => imgs.map((i) => i.naturalWidth));
  const ran = suite.cases.filter((c) => c.outcome !== 'error').length;
  check(thumbs.length === 2 * ran && thumbs.every((w) => w > 0), `${thumbs.length} thumbnails loaded, 2 per scene that ran`);

  // Sorting by a number column: ascending, then descending, the scenes without a number last.
  const column = (name) => page.locator('#scenes th.sort', { hasText: name });
  const values = async (index) => rows.evaluateAll((trs, i) => trs.map((tr) => tr.cells[i].dataset.value), index);
  const diffIndex = await column('largest difference').evaluate((th) => th.cellIndex);
  const ordered = (list, sign) => {
    const numbers = list.filter((v) => v !== '').map(Number);
    const tail = list.slice(numbers.length);
    return tail.every((v) => v === '') && numbers.every((v, i) => i === 0 || sign * (v - numbers[i - 1]) >= 0);
  };
  await column('largest difference').click();
  const up = await values(diffIndex);
  check(ordered(up, 1) && await column('largest difference').getAttribute('aria-sort') === 'ascending',
        `sorted by largest difference, ascending: ${up.join(',')}`);
  await column('largest difference').click();
  const down = await values(diffIndex);
  check(ordered(down, -1), `sorted by largest difference, descending: ${down.join(',')}`);
  await column('scene').click();
  const names = await rows.evaluateAll((trs) => trs.map((tr) => tr.cells[0].dataset.value));
  check(JSON.stringify(names) === JSON.stringify([...names].sort((a, b) => a.localeCompare(b))), 'sorted by scene name');
  await page.screenshot({ path: screenshot, fullPage: true });

  // A scene's name opens its page.
  const first = suite.cases.find((c) => c.outcome !== 'error');
  await page.locator(`#scenes a[href="${first.dir}/index.html"]`).click();
  await page.waitForSelector('body[data-pixels=ready]', { timeout: 30000 });
  check(page.url().endsWith(`/${first.dir}/index.html`), `opened ${first.dir}/index.html`);
  check(await page.locator('#stage').count() === 1, 'the scene page shows its images');
  check(errors.length === 0, 'no console errors' + (errors.length ? ': ' + errors.join(' | ') : ''));
} finally {
  await browser.close();
}
process.exit(exitStatus());
