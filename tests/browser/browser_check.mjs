// What every page check here shares: Debian's chromium through playwright-core (exit 77 when
// either is missing, so the gtest wrapper decides whether that skips or fails), the ok/FAIL
// lines and the exit status, and the console errors a page raises.
import fs from 'node:fs';

// Chromium, launched headless, or exit 77 naming what is missing.
export async function launchChromium() {
  const chromiumPath = process.env.TWINRASTER_CHROMIUM || '/usr/bin/chromium';
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch (err) {
    console.log('missing: playwright-core (npm ci in tests/browser; scripts/install-deps.sh does it): ' + err.message);
    process.exit(77);
  }
  if (!fs.existsSync(chromiumPath)) {
    console.log('missing: ' + chromiumPath + ' (Debian package chromium)');
    process.exit(77);
  }
  return chromium.launch({ executablePath: chromiumPath, headless: true, args: ['--no-sandbox'] });
}

// check(ok, what) prints one line per check; exitStatus() is 0 when every check held, else 1.
export function makeChecks() {
  const failures = [];
  const check = (ok, what) => { if (!ok) failures.push(what); console.log((ok ? 'ok   ' : 'FAIL ') + what); };
  return { check, exitStatus: () => (failures.length === 0 ? 0 : 1) };
}

// The console errors, uncaught exceptions and failed requests of `page`, collected as they come.
export function collectErrors(page) {
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('requestfailed', (r) => errors.push('request failed: ' + r.url()));
  return errors;
}
