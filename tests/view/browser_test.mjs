// The page of `yamsc view` in a real headless Chromium (playwright-core, the
// system's chromium): it loads with no console error, its animation advances,
// hovering a part names it, and the 3-D view shows the run (the share of pixels
// that are not the background, within bounds: no golden image).
//
// node browser_test.mjs PAGE.html SCREENSHOT.png MIN_SHARE MAX_SHARE
// env: YAMSC_NODE_MODULES (the build's viewer/npm/node_modules), CHROMIUM (path).
// Exit 0 pass, 1 fail, 77 skipped (no chromium).
import { createRequire } from 'node:module';
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

const [page_path, screenshot, minShareText, maxShareText] = process.argv.slice(2);
const executable = process.env.CHROMIUM || '/usr/bin/chromium';
if (!existsSync(executable)) {
    console.log(`skipped: no chromium at ${executable} (apt install chromium; scripts/install-deps.sh)`);
    process.exit(77);
}
const require = createRequire(`${process.env.YAMSC_NODE_MODULES}/`);
const { chromium } = require('playwright-core');

const failures = [];
const check = (ok, what) => { if (!ok) failures.push(what); console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`); };

const browser = await chromium.launch({
    executablePath: executable,
    headless: true,
    // WebGL without a GPU: SwiftShader through ANGLE.
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
           '--disable-background-networking', '--disable-component-update', '--disable-sync',
           '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
    const context = await browser.newContext({ viewport: { width: 1000, height: 760 } });
    // The page must need no network: every request but the page itself fails the test.
    const requests = [];
    await context.route('**/*', (route) => {
        const url = route.request().url();
        if (url.startsWith('file:') || url.startsWith('data:')) return route.continue();
        requests.push(url);
        return route.abort();
    });
    const page = await context.newPage();
    const errors = [];
    // Every error counts, and every warning but Chromium's own notes on its GL
    // driver (SwiftShader's "GPU stall due to ReadPixels" when a screenshot reads
    // the canvas back), which are not the page's.
    page.on('console', (m) => {
        const driverNote = m.type() === 'warning' && m.text().includes('GL Driver Message');
        if ((m.type() === 'error' || m.type() === 'warning') && !driverNote)
            errors.push(`console ${m.type()}: ${m.text()}`);
    });
    page.on('pageerror', (e) => errors.push(`page error: ${e.message}`));
    await page.goto(pathToFileURL(page_path).href, { waitUntil: 'load' });
    await page.waitForFunction(() => window.yamscView && window.yamscView.ready && window.yamscView.renders > 2,
                               null, { timeout: 30000 });

    const first = await page.evaluate(() => ({ time: yamscView.time, frame: yamscView.frame, frames: yamscView.frames }));
    await page.waitForTimeout(1500);
    const later = await page.evaluate(() => ({ time: yamscView.time, frame: yamscView.frame }));
    console.log(`frames ${first.frames}; t ${first.time.toFixed(3)} -> ${later.time.toFixed(3)}, frame ${first.frame} -> ${later.frame}`);
    check(first.frames > 1, 'the page holds more than one frame');
    check(later.time > first.time + 0.3, 'the animation advances (time)');
    check(later.frame > first.frame, 'the animation advances (frame)');

    // Pause, seek to the start: the frame shown is the first, the clock stops.
    await page.click('#play');
    await page.evaluate(() => yamscView.seek(0));
    const paused = await page.evaluate(() => ({ time: yamscView.time, frame: yamscView.frame, playing: yamscView.playing }));
    await page.waitForTimeout(300);
    const stillPaused = await page.evaluate(() => yamscView.time);
    check(!paused.playing && paused.frame === 0 && stillPaused === paused.time, 'pause and seek hold the first frame');

    // The share of the 3-D view that is not the background (#f4f6f8), from a
    // screenshot of it decoded in a page of its own (reading the WebGL canvas
    // back in the page would itself warn in its console).
    const shot = await page.locator('#view canvas').screenshot();
    const decoder = await context.newPage();
    const stats = await decoder.evaluate(async (b64) => {
        const image = new Image();
        image.src = `data:image/png;base64,${b64}`;
        await image.decode();
        const c = document.createElement('canvas');
        c.width = image.width;
        c.height = image.height;
        const g = c.getContext('2d');
        g.drawImage(image, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        let drawn = 0;
        let sx = 0;
        let sy = 0;
        for (let i = 0; i < d.length; i += 4) {
            if (Math.abs(d[i] - 0xf4) + Math.abs(d[i + 1] - 0xf6) + Math.abs(d[i + 2] - 0xf8) > 30) {
                const p = i / 4;
                drawn += 1;
                sx += p % c.width;
                sy += Math.floor(p / c.width);
            }
        }
        return { share: drawn / (c.width * c.height), cx: sx / Math.max(drawn, 1) / c.width,
                 cy: sy / Math.max(drawn, 1) / c.height, width: c.width, height: c.height };
    }, shot.toString('base64'));
    await decoder.close();
    console.log(`view ${stats.width}x${stats.height}: ${(100 * stats.share).toFixed(2)} % drawn, centroid (${stats.cx.toFixed(2)}, ${stats.cy.toFixed(2)})`);
    check(stats.share >= Number(minShareText) && stats.share <= Number(maxShareText),
          `the drawn share is within [${minShareText}, ${maxShareText}]`);
    check(stats.cx > 0.2 && stats.cx < 0.8 && stats.cy > 0.15 && stats.cy < 0.85, 'the run is framed near the middle');

    // Hovering the drawing names a part: the pointer on each point of the scene
    // in turn (as the screen shows it) until one names its part.
    const box = await page.locator('#view canvas').boundingBox();
    const points = await page.evaluate(() => {
        const out = [];
        const n = window.yamscView.pointCount;
        for (let i = 0; i < n; i += Math.max(1, Math.floor(n / 40))) out.push(yamscView.screenPosition(i));
        return out;
    });
    let hovered = null;
    for (const p of points) {
        if (p.x < box.x || p.y < box.y || p.x > box.x + box.width || p.y > box.y + box.height) continue;
        await page.mouse.move(p.x, p.y);
        hovered = await page.evaluate(() => yamscView.hovered);
        if (hovered) break;
    }
    const tip = hovered ? await page.locator('#tip').textContent() : '';
    console.log(`hovered part: ${hovered}`);
    check(Boolean(hovered) && tip === hovered, 'hovering the drawing shows a part name');
    await page.mouse.move(box.x + 2, box.y + 2);

    await page.screenshot({ path: screenshot });
    check(errors.length === 0, `no console error or warning${errors.length ? ': ' + errors.join(' | ') : ''}`);
    check(requests.length === 0, `no network request${requests.length ? ': ' + requests.join(' ') : ''}`);
} finally {
    await browser.close();
}
if (failures.length) {
    console.log(`${failures.length} check(s) failed`);
    process.exit(1);
}
