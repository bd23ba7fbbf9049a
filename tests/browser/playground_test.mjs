// Browser test of the playground page (GET /) against the real bezier-service binary,
// in Debian's headless Chromium driven by playwright-core (no browser download).
//
//   node tests/browser/playground_test.mjs --service build/service/bezier-service \
//        [--screenshot docs/playground.png]
//
// (or BEZIER_SERVICE_BINARY / PLAYGROUND_SCREENSHOT in the environment). Needs
// `npm ci` in tests/browser and /usr/bin/chromium (Debian packages chromium,
// chromium-driver). The page's answers are compared with the API's own answers to the
// same requests, fetched here from node; positions are computed here from the canvas
// box and the page's documented world (800 x 600 units, y up), not from the page.

import {after, before, test} from 'node:test';
import assert from 'node:assert/strict';
import {spawn} from 'node:child_process';
import {mkdtempSync, readFileSync, rmSync} from 'node:fs';
import {tmpdir} from 'node:os';
import {join} from 'node:path';
import {parseArgs} from 'node:util';
import {readPng} from './png.mjs';

let chromium;
try {
  ({chromium} = await import('playwright-core'));
} catch (e) {
  console.error(`playwright-core is not installed: run \`npm ci\` in tests/browser (${e.message})`);
  process.exit(1);
}

const {values: options} = parseArgs({
  options: {service: {type: 'string'}, screenshot: {type: 'string'}, chromium: {type: 'string'}},
});
const servicePath = options.service ?? process.env.BEZIER_SERVICE_BINARY;
const screenshotPath = options.screenshot ?? process.env.PLAYGROUND_SCREENSHOT ?? null;
const chromiumPath = options.chromium ?? process.env.CHROMIUM_PATH ?? '/usr/bin/chromium';
if (!servicePath) {
  console.error('usage: node playground_test.mjs --service PATH/bezier-service [--screenshot FILE.png]');
  process.exit(2);
}

const kMaxDegree = 5;  // the service runs with --max-degree 5, so 7 points must be refused
const kWorld = {width: 800, height: 600};
const kTimeout = 60_000;

let service;
let baseUrl;
let context;
let userDataDir;
let page;
const pageErrors = [];
// What the page's Content-Security-Policy blocked (Chromium reports each on the console).
const policyViolations = [];
const recordPolicyViolations = (p) => p.on('console', (message) => {
  if (/Content Security Policy/i.test(message.text())) policyViolations.push(message.text());
});

function startService() {
  return new Promise((resolve, reject) => {
    const child = spawn(servicePath, ['--host', '127.0.0.1', '--port', '0', '--max-degree', String(kMaxDegree),
                                      '--log-level', 'warn'], {stdio: ['ignore', 'pipe', 'inherit']});
    let text = '';
    const timer = setTimeout(() => reject(new Error(`no "listening on" line within 20 s: ${text}`)), 20_000);
    child.on('error', reject);
    child.on('exit', (code) => reject(new Error(`service exited early with ${code}: ${text}`)));
    child.stdout.on('data', (chunk) => {
      if (baseUrl) return;  // keep draining so the pipe never fills
      text += chunk;
      const match = text.match(/listening on (http:\/\/[^\s]+)/);
      if (match) {
        clearTimeout(timer);
        child.removeAllListeners('exit');
        resolve({child, url: match[1].replace(/\/$/, '')});
      }
    });
  });
}

async function api(route, body) {
  const response = await fetch(baseUrl + route, {
    method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body),
  });
  const answer = await response.json();
  assert.equal(response.status, 200, `${route} answered ${response.status}: ${JSON.stringify(answer)}`);
  return answer;
}

const settle = (p = page) => p.waitForFunction(() => window.playground && window.playground.idle, null, {timeout: kTimeout});
const pageState = (p = page) => p.evaluate(() => window.playground.state());
const pageAnswers = (p = page) => p.evaluate(() => window.playground.answers());
const pageErrorsShown = (p = page) => p.evaluate(() => window.playground.errors());

/** Client coordinates of world point w, from the canvas box and the world's definition. */
async function client(w, p = page) {
  const box = await p.locator('#scene').boundingBox();
  return [box.x + w[0] * box.width / kWorld.width, box.y + (kWorld.height - w[1]) * box.height / kWorld.height];
}

/** The canvas pixels [r, g, b, a] at world points ws, shifted dy CSS pixels down. */
async function pixelsAt(ws, dy = 0, p = page) {
  const box = await p.locator('#scene').boundingBox();
  const offsets = ws.map((w) => [w[0] * box.width / kWorld.width, (kWorld.height - w[1]) * box.height / kWorld.height + dy]);
  return p.evaluate((list) => {
    const canvas = document.getElementById('scene');
    const r = canvas.width / canvas.getBoundingClientRect().width;
    const ctx = canvas.getContext('2d');
    return list.map(([x, y]) => [...ctx.getImageData(Math.round(x * r), Math.round(y * r), 1, 1).data]);
  }, offsets);
}

/** The canvas pixel [r, g, b, a] at world point w, shifted dy CSS pixels down. */
const pixelAt = async (w, dy = 0) => (await pixelsAt([w], dy))[0];

async function clickWorld(w) {
  const [x, y] = await client(w);
  await page.mouse.click(x, y);
}

async function setMode(mode) {
  await page.locator(`#modes input[value=${mode}]`).check({force: true});
  assert.equal((await pageState()).mode, mode);
}

/** Numbers in a text such as "(392.5, 300)". */
const numbersIn = (text) => (text.match(/-?\d+(\.\d+)?(e[-+]?\d+)?/gi) ?? []).map(Number);

/** Equal answers; `stats` may carry timings, so there only the same keys and method. */
function assertSameAnswer(drawn, exact, what) {
  const {stats: drawnStats, ...drawnRest} = drawn ?? {};
  const {stats: exactStats, ...exactRest} = exact;
  assert.deepEqual(drawnRest, exactRest, what);
  assert.deepEqual(Object.keys(drawnStats ?? {}).sort(), Object.keys(exactStats ?? {}).sort(), `${what}: stats`);
  assert.equal(drawnStats?.method, exactStats?.method, `${what}: method`);
}

function assertClose(shown, exact, what) {
  assert.ok(Math.abs(shown - exact) <= 1e-5 * Math.max(1, Math.abs(exact)), `${what}: page shows ${shown}, API says ${exact}`);
}

before(async () => {
  ({child: service, url: baseUrl} = await startService());
  userDataDir = mkdtempSync(join(tmpdir(), 'bezier-playground-chromium-'));
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: chromiumPath,
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
    viewport: {width: 1280, height: 900},
    deviceScaleFactor: 1,
    hasTouch: true,
    acceptDownloads: true,
  });
  context.setDefaultTimeout(kTimeout);
  page = context.pages()[0] ?? await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(page);
});

after(async () => {
  await context?.close();
  if (userDataDir) rmSync(userDataDir, {recursive: true, force: true});
  if (service) {
    const exited = new Promise((resolve) => service.once('exit', (code, signal) => resolve({code, signal})));
    service.kill('SIGTERM');
    const {code} = await exited;
    assert.equal(code, 0, 'the service exits 0 on SIGTERM');
  }
});

test('GET / serves the page and its files with their content types', async () => {
  for (const [path, type] of [['/', 'text/html'], ['/playground/app.js', 'text/javascript'],
                              ['/playground/style.css', 'text/css']]) {
    const response = await fetch(baseUrl + path);
    assert.equal(response.status, 200, path);
    assert.match(response.headers.get('content-type'), new RegExp(`^${type}`), path);
    assert.equal(response.headers.get('x-content-type-options'), 'nosniff', path);
  }
  // The page runs under a policy that admits nothing but its own origin: no inline
  // script or style, no other host. Every test below runs under it, and a violation
  // (recorded from the console) fails the last one.
  const policy = (await fetch(baseUrl + '/')).headers.get('content-security-policy') ?? '';
  assert.match(policy, /(^|;\s*)default-src 'self'(;|$)/);
  assert.match(policy, /(^|;\s*)frame-ancestors 'none'(;|$)/);
  await page.goto(baseUrl + '/');
  await settle();
  assert.equal(await page.title(), 'Bézier playground · bezier-service');
  // With no drawing in the link, the page opens on an example: two curves, drawn and intersected.
  const opened = await pageState();
  assert.equal(opened.second, true);
  assert.ok(opened.curves.every((c) => c.points.length >= 2), 'both curves have control points');
  const openedAnswers = await pageAnswers();
  assert.ok(openedAnswers.curves[0].evaluate && openedAnswers.curves[1].evaluate, 'both curves are drawn');
  assertSameAnswer(openedAnswers.intersections,
                   await api('/intersections', {curves: opened.curves.map((c) => ({points: c.points}))}), 'the example\'s intersections');
  assert.ok(openedAnswers.intersections.intersections.length >= 1, 'the example curves cross');
  assert.ok(await page.locator('#hint').isHidden(), 'no "click to add" hint over an example');
  // A link with an empty drawing opens an empty grid.
  await page.goto(baseUrl + '/#a=&t0=0.5');
  await page.waitForFunction(() => window.playground.state().curves[0].points.length === 0 && !window.playground.state().second);
  await settle();
  assert.deepEqual((await pageState()).curves.map((c) => c.points), [[], []]);
});

const kFour = [[100, 120], [240, 480], [560, 500], [700, 140]];
const kMoved = [300, 560];

test('adds four points where the mouse clicks, and draws the API\'s curve', async () => {
  await setMode('add');
  for (const w of kFour) await clickWorld(w);
  await settle();
  const state = await pageState();
  assert.deepEqual(state.curves[0].points, kFour);
  // The page's mapping agrees with the test's to within a pixel.
  const [px, py] = await page.evaluate((w) => window.playground.clientPoint(w), kFour[1]);
  const [tx, ty] = await client(kFour[1]);
  assert.ok(Math.abs(px - tx) < 1 && Math.abs(py - ty) < 1);
  const drawn = (await pageAnswers()).curves[0].evaluate;
  assert.deepEqual(drawn, await api('/evaluate', {points: kFour, samples: drawn.results.length}));
  assert.match(await page.locator('#value-degree').textContent(), /4 control points, degree 3/);
});

test('Move mode highlights the point under the cursor and drags it', async () => {
  await setMode('move');
  const [x, y] = await client(kFour[1]);
  await page.mouse.move(x, y);
  assert.deepEqual(await page.evaluate(() => window.playground.hover()), {curve: 0, index: 1});
  assert.ok(await page.locator('#scene.over-point').count() === 1, 'the cursor shows a point is under it');
  assert.match(await page.locator('#bernstein-caption').textContent(), /degree 3/);
  await page.mouse.down();
  const [tx, ty] = await client(kMoved);
  await page.mouse.move(tx, ty, {steps: 12});
  await page.mouse.up();
  await settle();
  const points = (await pageState()).curves[0].points;
  assert.deepEqual(points, [kFour[0], kMoved, kFour[2], kFour[3]]);
  const drawn = (await pageAnswers()).curves[0].evaluate;
  assert.deepEqual(drawn, await api('/evaluate', {points, samples: drawn.results.length}));
});

test('t0: slider and a two-decimal field clamped to [0, 1]; the page shows the API\'s polar', async () => {
  const number = page.locator('#t0-number');
  const setNumber = async (text) => {
    await number.fill(text);
    await number.press('Tab');
  };
  await setNumber('0.333');
  assert.equal(await number.inputValue(), '0.33');
  assert.equal((await pageState()).t0, 0.33);
  await setNumber('1.7');
  assert.equal(await number.inputValue(), '1.00');
  assert.equal((await pageState()).t0, 1);
  await setNumber('-0.25');
  assert.equal(await number.inputValue(), '0.00');
  await page.locator('#t0-range').focus();
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('ArrowRight');
  assert.equal(await number.inputValue(), '0.02', 'the slider steps by 0.01 and updates the field');
  await setNumber('0.37');
  assert.equal(await page.locator('#t0-range').inputValue(), '0.37');
  await settle();

  const state = await pageState();
  assert.equal(state.t0, 0.37);
  const polar = (await pageAnswers()).polar;
  const exact = await api('/polar', {points: state.curves[0].points, t0: 0.37, samples: polar.results.length});
  const {curve, ...drawn} = polar;
  assert.equal(curve, 0);
  assert.deepEqual(drawn, exact);
  assert.equal(exact.control_points.length, 3);
  const shown = numbersIn(await page.locator('#value-curve-point').textContent());
  assert.equal(shown.length, 2);
  shown.forEach((v, k) => assertClose(v, exact.curve_point[k], `B(t0)[${k}]`));
  const shownPolar = numbersIn((await page.locator('#value-polar-points').textContent()).replace(/b[₀-₉]+¹/g, ''));
  assert.equal(shownPolar.length, 6);
  shownPolar.forEach((v, k) => assertClose(v, exact.control_points[k >> 1][k & 1], `polar point ${k >> 1}`));
  assert.equal(await page.locator('#value-t0').textContent(), '0.37');
});

/** B(t) and B'(t) by de Casteljau on the hodograph, computed here, independently of the page. */
function casteljau(points, t) {
  let level = points.map((p) => [...p]);
  while (level.length > 1) level = level.slice(1).map((p, i) => p.map((v, k) => (1 - t) * level[i][k] + t * v));
  return level[0];
}

const hodograph = (points) => points.slice(1).map((p, i) => p.map((v, k) => (points.length - 1) * (v - points[i][k])));

test('the edited curve measured: box and extremes, lengths, tangent, normal and osculating circle at t0', async () => {
  const state = await pageState();
  const points = state.curves[0].points;
  const t0 = state.t0;
  const m = (await pageAnswers()).measure;
  assert.equal(m.curve, 0);
  assert.deepEqual(m.bounds, await api('/bounds', {points}));
  assert.deepEqual(m.length, await api('/length', {points}));
  assert.deepEqual(m.lengthToT0, await api('/length', {points, interval: [0, t0]}));
  assert.deepEqual(m.frame, (await api('/evaluate', {points, t: t0, frame: true})).results[0]);

  // The lengths add up over [0, t0] and [t0, 1]; the page shows both.
  const rest = await api('/length', {points, interval: [t0, 1]});
  assert.ok(Math.abs(m.lengthToT0.length + rest.length - m.length.length) <= 1e-9 * m.length.length);
  assertClose(numbersIn(await page.locator('#value-length').textContent())[0], m.length.length, 'length');
  assertClose(numbersIn(await page.locator('#value-length-t0').textContent())[0], m.lengthToT0.length, 'length of [0, t0]');

  // The box holds every sample of the curve, and each face is reached by an end or by
  // the curve's point at a critical parameter the page drew.
  const scale = 800;
  for (let k = 0; k <= 400; ++k) {
    const p = casteljau(points, k / 400);
    for (const axis of [0, 1]) {
      assert.ok(p[axis] >= m.bounds.min[axis] - 1e-9 * scale && p[axis] <= m.bounds.max[axis] + 1e-9 * scale);
    }
  }
  const candidates = [points[0], points[points.length - 1], ...m.extremes.map((e) => e.point)];
  for (const axis of [0, 1]) {
    for (const face of [m.bounds.min[axis], m.bounds.max[axis]]) {
      assert.ok(candidates.some((p) => Math.abs(p[axis] - face) <= 1e-9 * scale), `face ${face} of axis ${axis} is reached`);
    }
  }
  for (const e of m.extremes) {
    casteljau(points, e.t).forEach((v, k) => assert.ok(Math.abs(v - e.point[k]) <= 1e-9 * scale));
    assert.ok(m.bounds.critical[e.axis].includes(e.t));
  }
  assert.ok(m.extremes.length >= 1, 'this curve turns inside its box');
  const box = numbersIn(await page.locator('#value-box').textContent());
  [...m.bounds.min, ...m.bounds.max].forEach((v, k) => assertClose(box[k], v, `box ${k}`));

  // The frame from the derivatives computed here: T = B'/|B'|, N = T turned +90°,
  // kappa = (x'y'' - y'x'') / |B'|^3, centre B + N / kappa, radius 1 / |kappa|.
  const d1 = casteljau(hodograph(points), t0);
  const d2 = casteljau(hodograph(hodograph(points)), t0);
  const speed = Math.hypot(d1[0], d1[1]);
  const tangent = [d1[0] / speed, d1[1] / speed];
  const normal = [-tangent[1], tangent[0]];
  const kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / speed ** 3;
  const point = casteljau(points, t0);
  const centre = [point[0] + normal[0] / kappa, point[1] + normal[1] / kappa];
  numbersIn(await page.locator('#value-tangent').textContent()).forEach((v, k) => assertClose(v, tangent[k], 'tangent'));
  numbersIn(await page.locator('#value-normal').textContent()).forEach((v, k) => assertClose(v, normal[k], 'normal'));
  assertClose(numbersIn(await page.locator('#value-curvature').textContent())[0], kappa, 'curvature');
  const [radius, cx, cy] = numbersIn(await page.locator('#value-osculating').textContent());
  assertClose(radius, 1 / Math.abs(kappa), 'radius');
  assertClose(cx, centre[0], 'centre x');
  assertClose(cy, centre[1], 'centre y');

  // Drawn: the circle's pixels, and the box's dashed frame, go with their check boxes.
  const onCircle = [];
  for (let k = 0; k < 24; ++k) {
    const a = 2 * Math.PI * k / 24;
    const w = [centre[0] + Math.cos(a) / Math.abs(kappa), centre[1] + Math.sin(a) / Math.abs(kappa)];
    if (w[0] > 10 && w[0] < 790 && w[1] > 10 && w[1] < 590) onCircle.push(w);
  }
  assert.ok(onCircle.length >= 6, 'the osculating circle is in view');
  const alphas = async (ws) => (await pixelsAt(ws)).map((px) => px[3]);
  const withFrame = await alphas(onCircle);
  await page.locator('#show-frame').uncheck();
  const withoutFrame = await alphas(onCircle);
  await page.locator('#show-frame').check();
  const changedPixels = withFrame.filter((a, k) => a > withoutFrame[k]).length;
  assert.ok(changedPixels >= onCircle.length / 2, `the circle is drawn at ${changedPixels} of ${onCircle.length} points`);
  const boxEdge = [...Array(9).keys()].map((k) => [m.bounds.min[0] + (m.bounds.max[0] - m.bounds.min[0]) * (k + 0.5) / 9, m.bounds.min[1]]);
  const withBox = await alphas(boxEdge);
  await page.locator('#show-box').uncheck();
  const withoutBox = await alphas(boxEdge);
  await page.locator('#show-box').check();
  assert.ok(withBox.filter((a, k) => a > withoutBox[k]).length >= 3, 'the box\'s lower edge is drawn');
});

test('the nearest point under the pointer: the API\'s answer, one request at a time', async () => {
  const points = (await pageState()).curves[0].points;
  let open = 0;
  let mostOpen = 0;
  const isNearest = (request) => request.url().endsWith('/nearest');
  const opened = (request) => { if (isNearest(request)) mostOpen = Math.max(mostOpen, ++open); };
  const closed = (request) => { if (isNearest(request)) --open; };
  page.on('request', opened);
  page.on('requestfinished', closed);
  page.on('requestfailed', closed);
  const sentBefore = (await page.evaluate(() => window.playground.nearest())).sent;
  const [x0, y0] = await client([120, 560]);
  const q = [640, 420];
  const [x1, y1] = await client(q);
  await page.mouse.move(x0, y0);
  await page.mouse.move(x1, y1, {steps: 40});
  const result = await page.waitForFunction(([qx, qy]) => {
    const n = window.playground.nearest();
    return !n.inFlight && n.result && Math.abs(n.result.target[0] - qx) < 1 && Math.abs(n.result.target[1] - qy) < 1 && n;
  }, q, {timeout: kTimeout}).then((h) => h.jsonValue());
  page.off('request', opened);
  page.off('requestfinished', closed);
  page.off('requestfailed', closed);
  assert.ok(mostOpen === 1, `${mostOpen} /nearest requests were out at once`);
  assert.ok(result.sent > sentBefore, 'the pointer asked');
  const exact = (await api('/nearest', {points, targets: [result.result.target]})).results[0];
  assert.deepEqual(result.result.answer, exact);
  // No sampled point of the curve is nearer.
  const [tx, ty] = result.result.target;
  for (let k = 0; k <= 2000; ++k) {
    const p = casteljau(points, k / 2000);
    assert.ok(Math.hypot(p[0] - tx, p[1] - ty) >= exact.distance - 1e-9 * 800);
  }
  const shown = numbersIn(await page.locator('#value-nearest').textContent());
  assertClose(shown[shown.length - 1], exact.distance, 'distance shown');
  // The segment to the nearest point is drawn at its middle.
  const middle = [(tx + exact.point[0]) / 2, (ty + exact.point[1]) / 2];
  assert.ok((await pixelAt(middle))[3] > 0 || (await pixelAt(middle, 1))[3] > 0, 'the segment to the nearest point is drawn');
  await page.mouse.move(5, 5);
});

test('Remove mode removes the point under the cursor', async () => {
  await setMode('remove');
  const [x, y] = await client(kFour[2]);
  await page.mouse.move(x, y);
  assert.deepEqual(await page.evaluate(() => window.playground.hover()), {curve: 0, index: 2});
  await page.mouse.click(x, y);
  await settle();
  const points = (await pageState()).curves[0].points;
  assert.deepEqual(points, [kFour[0], kMoved, kFour[3]]);
  const answers = await pageAnswers();
  assert.deepEqual(answers.curves[0].evaluate, await api('/evaluate', {points, samples: answers.curves[0].evaluate.results.length}));
  assert.equal(answers.polar.degree, 1);
  assert.match(await page.locator('#value-degree').textContent(), /degree 2/);
  assert.deepEqual(await pageErrorsShown(), []);
});

test('past the degree limit: the point is refused with a message beside the canvas, the curve stays', async () => {
  await setMode('add');
  for (const w of [[400, 60], [460, 60], [520, 60]]) await clickWorld(w);
  await settle();
  const full = (await pageState()).curves[0].points;
  assert.equal(full.length, kMaxDegree + 1);
  assert.equal(await page.evaluate(() => window.playground.degreeLimit()), null, 'no refusal yet');
  await clickWorld([580, 60]);
  await settle();
  // The service refused degree 6; the page took the point back and says why, once.
  assert.deepEqual((await pageState()).curves[0].points, full);
  assert.equal(await page.evaluate(() => window.playground.degreeLimit()), kMaxDegree);
  const message = page.locator('#canvas-message');
  await message.waitFor({state: 'visible'});
  assert.match(await message.textContent(), new RegExp(`degree at most ${kMaxDegree} \\(${kMaxDegree + 1} control points\\)`));
  assert.equal(await page.locator('#errors li, #points-errors li').count(), 0, 'no request error is left listed');
  const drawn = (await pageAnswers()).curves[0].evaluate;
  assert.deepEqual(drawn, await api('/evaluate', {points: full, samples: drawn.results.length}), 'the curve is still drawn');
  // Known now: the next point is refused at once.
  await clickWorld([640, 60]);
  assert.equal((await pageState()).curves[0].points.length, kMaxDegree + 1);
  assert.match(await message.textContent(), /would have 7/);
  await page.locator('#clear').click();
  await settle();
  assert.ok(await message.isHidden(), 'the message goes with the next edit');
});

const kCrossing = [[620, 240], [20, 100], [20, 300], [560, 240]];

test('loops shaded with their area; the cubic\'s type and canonical point', async () => {
  await page.locator('#examples').selectOption('loop');
  await settle();
  const a = (await pageState()).curves[0].points;
  assert.equal(a.length, 4);
  const answers = await pageAnswers();
  const loops = await api('/loop-area', {points: a});
  assert.ok(loops.loops.length >= 1, 'the example cubic has a loop');
  assertSameAnswer(answers.curves[0].loopArea, loops, '/loop-area');
  assert.equal(answers.curves[0].loopPaths.length, loops.loops.length);
  const loopItems = page.locator('#loops li[data-curve=A]');
  assert.equal(await loopItems.count(), loops.loops.length);
  const areaShown = numbersIn((await loopItems.first().textContent()).split('area')[1]);
  assertClose(areaShown[0], loops.loops[0].area, 'loop area');
  // The shading is drawn: the canvas is not transparent at the loop's centre.
  const path = answers.curves[0].loopPaths[0].points;
  const centre = [path.reduce((s, p) => s + p[0], 0) / path.length, path.reduce((s, p) => s + p[1], 0) / path.length];
  const alphaInside = async () => (await pixelAt(centre, 12))[3];  // a little below the area label
  assert.ok(await alphaInside() > 0, 'the loop is shaded');
  await page.locator('#show-loops').uncheck();
  assert.equal(await alphaInside(), 0, 'without "Loops and areas" the inside is not painted');
  await page.locator('#show-loops').check();

  const type = await api('/classify', {points: a});
  assert.deepEqual(answers.curves[0].classify, type);
  assert.equal(type.type, 'loop');
  assert.equal(await page.locator('#types li[data-curve=A] .type').textContent(), type.type);
  const canonical = numbersIn((await page.locator('#types li[data-curve=A] .small').textContent()).split('canonical P3')[1]);
  assertClose(canonical[0], type.canonical_point[0], 'canonical x');
  assertClose(canonical[1], type.canonical_point[1], 'canonical y');
  assert.equal(await page.locator('#canonical').getAttribute('data-edges'), 'cusp; loop at t = 0; loop at t = 1; inflection at t = 1',
               'the map names its edges');
  assert.deepEqual(await pageErrorsShown(), []);
});

/** De Casteljau's levels at t, computed here: levels[r][i] = b_i^r. */
function casteljauLevels(points, t) {
  const levels = [points.map((p) => [...p])];
  while (levels[levels.length - 1].length > 1) {
    const last = levels[levels.length - 1];
    levels.push(last.slice(1).map((p, i) => p.map((v, k) => (1 - t) * last[i][k] + t * v)));
  }
  return levels;
}

/** [r, g, b] of a CSS colour such as '#1e88e5' or 'rgb(30, 136, 229)'. */
function rgbOf(color) {
  if (color.startsWith('#')) return [1, 3, 5].map((k) => parseInt(color.slice(k, k + 2), 16));
  return color.match(/\d+/g).slice(0, 3).map(Number);
}
const near = (pixel, rgb, tolerance = 40) => rgb.every((v, k) => Math.abs(pixel[k] - v) <= tolerance);

test('de Casteljau\'s construction at t0: every level from the API, coloured and labelled b_i^r; t0 animates', async () => {
  const state = await pageState();
  const points = state.curves[0].points;
  const t0 = state.t0;
  const n = points.length - 1;
  assert.equal(n, 3);
  const answers = await pageAnswers();
  const {levels, curve} = answers.casteljau;
  assert.equal(curve, 0);
  assert.equal(levels.length, n + 1);
  const exact = casteljauLevels(points, t0);
  levels.forEach((level, r) => {
    assert.equal(level.length, n + 1 - r, `level ${r} has ${n + 1 - r} points`);
    level.forEach((p, i) => p.forEach((v, k) => assert.ok(Math.abs(v - exact[r][i][k]) <= 1e-9 * 800, `b_${i}^${r}`)));
  });
  // Level 1 is the first polar's control points; level r the r-th polar's; level n is B(t0).
  assert.deepEqual(levels[1], answers.polar.control_points);
  for (let r = 2; r < n; ++r) {
    assert.deepEqual(levels[r], (await api('/polar', {points, t0: Array(r).fill(t0)})).control_points);
  }
  assert.deepEqual(levels[n], [answers.polar.curve_point]);
  const sub = '₀₁₂₃₄₅₆₇₈₉';
  const sup = '⁰¹²³⁴⁵⁶⁷⁸⁹';
  const {placed, dropped} = await page.evaluate(() => window.playground.labels());
  const texts = new Set([...placed.map((b) => b.text), ...dropped]);
  for (let r = 1; r < n; ++r) {
    for (let i = 0; i <= n - r; ++i) assert.ok(texts.has(`b${sub[i]}${sup[r]}`), `b_${i}^${r} is labelled`);
  }
  // Level 2's points in level 2's colour, level 1's in the polar's (the legend shows both).
  const level2 = rgbOf('#1e88e5');
  const polar = rgbOf('#8a3fd1');
  const colored = async (level, rgb) => (await pixelsAt(level)).filter((px) => near(px, rgb)).length;
  assert.ok(await colored(levels[2], level2) >= 1, 'level 2 drawn in its colour');
  assert.ok(await colored(levels[1], polar) >= 2, 'level 1 drawn in the polar\'s colour');
  await page.locator('#show-casteljau').uncheck();
  await settle();
  assert.equal((await pageAnswers()).casteljau, null, 'no construction asked for when it is hidden');
  assert.equal(await colored(levels[2], level2), 0, 'level 2 gone');
  await page.locator('#show-casteljau').check();
  await settle();

  // Animation: t0 moves in steps of 0.01 and each step is answered; Stop keeps the last.
  const animate = page.locator('#animate');
  await animate.click();
  assert.equal(await animate.getAttribute('aria-pressed'), 'true');
  await page.waitForFunction((start) => Math.abs(window.playground.state().t0 - start) >= 0.05, t0, {timeout: kTimeout});
  await animate.click();
  assert.equal(await animate.getAttribute('aria-pressed'), 'false');
  await settle();
  const stopped = (await pageState()).t0;
  assert.notEqual(stopped, t0);
  assert.equal(Math.round(stopped * 100) / 100, stopped, 'two decimals');
  assert.equal((await pageAnswers()).casteljau.t0, stopped, 'the construction drawn is the one at the t0 shown');
  await page.waitForTimeout(150);
  assert.equal((await pageState()).t0, stopped, 'stopped');
  await page.locator('#t0-number').fill(String(t0));
  await page.locator('#t0-number').press('Tab');
  await settle();
});

const binomial = (n, k) => {
  let c = 1;
  for (let j = 1; j <= k; ++j) c = c * (n - k + j) / j;
  return c;
};

test('Bernstein basis: a colour per B_{i,n} matching its control point, a legend with the values at t0', async () => {
  const state = await pageState();
  const points = state.curves[0].points;
  const {t0} = state;
  const n = points.length - 1;
  const items = page.locator('#bernstein-legend li[data-index]');
  assert.equal(await items.count(), n + 1);
  let sum = 0;
  const weighted = [0, 0];
  for (let i = 0; i <= n; ++i) {
    const item = items.nth(i);
    const exact = binomial(n, i) * t0 ** i * (1 - t0) ** (n - i);
    const value = Number(await item.getAttribute('data-value'));
    assert.ok(Math.abs(value - exact) <= 1e-15, `B_${i},${n}(t0)`);
    assert.ok(Math.abs(Number(await item.locator('.value').textContent()) - exact) <= 5e-5, 'shown to 4 decimals');
    assert.match(await item.textContent(), new RegExp(`weight of P${i}`));
    sum += exact;
    weighted[0] += exact * points[i][0];
    weighted[1] += exact * points[i][1];
    // The swatch's colour is the colour the control point is filled with on the canvas.
    const swatch = rgbOf(await item.locator('.swatch').evaluate((e) => getComputedStyle(e).backgroundColor));
    const filled = await pixelAt(points[i]);
    assert.ok(near(filled, swatch, 30), `P${i} is filled in B_${i},${n}'s colour: ${filled} against ${swatch}`);
  }
  assert.ok(Math.abs(sum - 1) < 1e-12);
  // The weights give B(t0): the API's point.
  const curvePoint = (await pageAnswers()).polar.curve_point;
  weighted.forEach((v, k) => assert.ok(Math.abs(v - curvePoint[k]) <= 1e-9 * 800));
  // In the plot, B_{i,n}(t0) is marked on the t0 line in the same colour.
  const plot = await page.locator('#bernstein').boundingBox();
  const i = 1;
  const swatch = rgbOf(await items.nth(i).locator('.swatch').evaluate((e) => getComputedStyle(e).backgroundColor));
  const value = binomial(n, i) * t0 ** i * (1 - t0) ** (n - i);
  const mark = await page.evaluate(([t, v]) => {
    const canvas = document.getElementById('bernstein');
    const r = canvas.width / canvas.getBoundingClientRect().width;
    const w = canvas.clientWidth - 26 - 8;
    const h = canvas.clientHeight - 8 - 18;
    return [...canvas.getContext('2d').getImageData(Math.round((26 + t * w) * r), Math.round((8 + (1 - v) * h) * r), 1, 1).data];
  }, [t0, value]);
  assert.ok(plot.width > 0);
  assert.ok(near(mark, swatch, 40), `B_${i},${n}(t0) marked in its colour, got ${mark}`);
});

test('control point colours stay distinct past twelve points, up to the service\'s default degree limit (20)', async () => {
  // The page's palette, asked of the module the page runs (the service here stops at degree 5).
  const colors = await page.evaluate(async () => {
    const {pointColor} = await import('/playground/draw.js');
    const probe = document.createElement('span');
    document.body.append(probe);
    const out = [];
    for (let i = 0; i <= 20; ++i) {
      probe.style.color = pointColor(i);
      out.push(getComputedStyle(probe).color);
    }
    probe.remove();
    return out;
  });
  const rgb = colors.map(rgbOf);
  assert.equal(new Set(colors).size, colors.length, 'no two points share a colour');
  let least = Infinity;
  for (let i = 0; i < rgb.length; ++i) {
    for (let j = i + 1; j < rgb.length; ++j) least = Math.min(least, Math.hypot(...rgb[i].map((v, k) => v - rgb[j][k])));
  }
  assert.ok(least >= 40, `the closest two colours are ${least.toFixed(1)} apart in RGB`);
});

test('explanations: a legend entry for every mark shown, a line per panel, search statistics folded', async () => {
  const marks = async () => page.locator('#legend li').evaluateAll((items) => items.map((li) => li.dataset.mark));
  const shown = await marks();
  for (const mark of ['points', 'polygon', 'curve-a', 'polar', 'polar-points', 'curve-point', 'tangent', 'osculating',
                      'box', 'nearest', 'loop', 'inflection', 'cusp']) {
    assert.ok(shown.includes(mark), `the legend explains ${mark}`);
  }
  await page.locator('#show-box').uncheck();
  assert.ok(!(await marks()).includes('box'), 'a hidden mark leaves the legend');
  await page.locator('#show-box').check();
  for (const panel of ['#classify-section', '#intersections', '#loops', '#bernstein', '#values']) {
    const text = await page.locator(panel).locator('xpath=ancestor-or-self::section[1]').locator('.explain').textContent();
    assert.ok(text.trim().length > 30, `${panel} says what it shows`);
  }
  assert.match(await page.locator('#classify-section .explain').textContent(), /Loop–Blinn/);
  assert.match(await page.locator('#classify-section .explain').textContent(), /Canonical form/);
});

test('second curve: intersections marked, their kind shown on hover', async () => {
  const a = (await pageState()).curves[0].points;
  await page.locator('#show-second').check();
  assert.equal((await pageState()).active, 1, 'turning the second curve on edits it');
  await setMode('add');
  for (const w of kCrossing) await clickWorld(w);
  await settle();
  assert.deepEqual((await pageState()).curves[1].points, kCrossing);
  const answers = await pageAnswers();

  const exact = await api('/intersections', {curves: [{points: a}, {points: kCrossing}]});
  assertSameAnswer(answers.intersections, exact, '/intersections');
  assert.ok(exact.intersections.length >= 2, 'the example curves cross');
  const items = page.locator('#intersections li[data-index]');
  assert.equal(await items.count(), exact.intersections.length);
  for (let k = 0; k < exact.intersections.length; ++k) {
    assert.equal(await items.nth(k).getAttribute('data-kind'), exact.intersections[k].kind);
  }
  const stats = page.locator('#intersections details.stats');
  assert.equal(await stats.count(), 1);
  assert.equal(await stats.evaluate((d) => d.open), false, 'search statistics are folded by default');
  assert.ok(await stats.locator('div').isHidden());
  await stats.locator('summary').click();
  assert.match(await stats.locator('div').textContent(), /iterations/);
  await stats.locator('summary').click();
  await setMode('move');
  const hit = exact.intersections[0];
  const [x, y] = await client(hit.point);
  await page.mouse.move(x, y);
  const tooltip = page.locator('#tooltip');
  await tooltip.waitFor({state: 'visible'});
  assert.match(await tooltip.textContent(), new RegExp(`^${hit.kind} intersection`));
  assert.equal(await page.locator('#intersections li.active').getAttribute('data-index'), '0');
  const type = await api('/classify', {points: kCrossing});
  assert.deepEqual(answers.curves[1].classify, type);
  assert.equal(await page.locator('#types li[data-curve=B] .type').textContent(), type.type);
  assert.deepEqual(await pageErrorsShown(), []);

  await page.mouse.move(5, 5);
  await tooltip.waitFor({state: 'hidden'});
  assert.equal(await page.locator('#intersections li.active').count(), 0);

  // The picture for the README: A's polar at t0 = 0.37, B's intersections, one hovered.
  await page.locator('#editing input[value="0"]').check({force: true});
  await settle();
  const last = exact.intersections[exact.intersections.length - 1];
  const [lx, ly] = await client(last.point);
  await page.mouse.move(lx, ly);
  await tooltip.waitFor({state: 'visible'});
  assert.match(await tooltip.textContent(), new RegExp(`^${last.kind} intersection`));
  if (screenshotPath) await page.screenshot({path: screenshotPath, fullPage: true});
  await page.mouse.move(5, 5);
});

test('the PNG download: twice the resolution, a white background, the legend under the drawing', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#download').click()]);
  assert.equal(download.suggestedFilename(), 'bezier-playground.png');
  const png = readPng(readFileSync(await download.path()));
  const box = await page.locator('#scene').boundingBox();
  assert.equal(png.width, 2 * Math.round(box.width));
  const drawingHeight = 2 * Math.round(box.height);
  assert.ok(png.height > drawingHeight + 100, `the legend adds rows below the drawing (${png.height} px)`);
  const pixel = (x, y) => [...png.pixels.subarray(4 * (y * png.width + x), 4 * (y * png.width + x) + 4)];
  assert.deepEqual(pixel(0, 0), [255, 255, 255, 255], 'white, opaque corner');
  assert.deepEqual(pixel(png.width - 1, png.height - 1), [255, 255, 255, 255], 'white, opaque far corner');
  let transparent = 0;
  for (let k = 3; k < png.pixels.length; k += 4) if (png.pixels[k] !== 255) ++transparent;
  assert.equal(transparent, 0, 'no transparent pixel');
  // Curve A's colour at a sample of the curve (scaled by 2).
  const state = await pageState();
  const samples = (await pageAnswers()).curves[0].evaluate.results;
  const blue = samples.filter((r, k) => k % 16 === 8).filter((r) => {
    const x = Math.round(r.point[0] * png.width / kWorld.width);
    const y = Math.round((kWorld.height - r.point[1]) * drawingHeight / kWorld.height);
    const [red, green, b] = pixel(Math.min(png.width - 1, x), Math.min(drawingHeight - 1, y));
    return b > 150 && red < 120 && green < 160;
  });
  assert.ok(blue.length >= 4, `curve ${state.curves[0].name} is drawn in its colour (${blue.length} samples)`);
  // The legend's text: dark pixels in the band under the drawing.
  let dark = 0;
  for (let k = 4 * (drawingHeight + 4) * png.width; k < png.pixels.length; k += 4) {
    if (png.pixels[k] < 80 && png.pixels[k + 1] < 80) ++dark;
  }
  assert.ok(dark > 2000, `the legend is written under the drawing (${dark} dark pixels)`);
});

test('overlapping curves: the overlap is listed and highlighted', async () => {
  await page.locator('#examples').selectOption('overlap');
  await settle();
  const state = await pageState();
  const exact = await api('/intersections', {curves: [{points: state.curves[0].points}, {points: state.curves[1].points}]});
  assert.ok(exact.overlaps.length >= 1, 'the API reports the overlap');
  const answers = await pageAnswers();
  assertSameAnswer(answers.intersections, exact, '/intersections');
  assert.equal(await page.locator('#intersections li[data-kind=overlap]').count(), exact.overlaps.length);
  assert.equal(answers.curves[0].overlapPaths.length, exact.overlaps.length);
  assert.equal(answers.curves[1].overlapPaths.length, exact.overlaps.length);
  // Highlighted: a yellow band along the piece, beside the curves' own lines.
  const piece = answers.curves[0].overlapPaths[0];
  const spot = piece[Math.round(piece.length * 0.7)];
  const [r, g, b, alpha] = await pixelAt(spot, 4);
  assert.ok(alpha > 0 && r > b + 60 && g > b + 30, `yellow at the overlap, got rgba(${r}, ${g}, ${b}, ${alpha})`);
  await page.locator('#show-intersections').uncheck();
  const [, , , plain] = await pixelAt(spot, 4);
  assert.ok(plain < alpha, 'the band goes with the Intersections check box');
  await page.locator('#show-intersections').check();
});

/** Puts `text` in the paste box and uses it; returns the message shown beside it. */
async function paste(text) {
  await page.locator('#paste-text').fill(text);
  await page.locator('#paste-form button[type=submit]').click();
  // Path data goes to the service (/segments) first: the message comes with its answer.
  await page.locator('#paste-message').waitFor({state: 'visible'});
  return page.locator('#paste-message').textContent();
}

test('exact input: the table, pasted points and SVG path data, undo and redo, the permalink', async () => {
  await page.locator('#examples').selectOption('loop');
  await settle();
  const loop = (await pageState()).curves[0].points;
  const rows = page.locator('#points-table tbody tr');
  assert.equal(await rows.count(), 4);
  const field = (row, axis) => rows.nth(row).locator(`input[data-axis="${axis}"]`);
  assert.equal(await field(1, 0).inputValue(), String(loop[1][0]));
  await field(1, 0).fill('333.25');
  await field(1, 0).press('Enter');
  await settle();
  const typed = (await pageState()).curves[0].points;
  assert.deepEqual(typed, [loop[0], [333.25, loop[1][1]], loop[2], loop[3]]);
  const drawn = (await pageAnswers()).curves[0].evaluate;
  assert.deepEqual(drawn, await api('/evaluate', {points: typed, samples: drawn.results.length}));
  // Not a number: refused beside the table, once, and nothing changes.
  await field(2, 1).fill('abc');
  await field(2, 1).press('Tab');
  const message = page.locator('#points-message');
  await message.waitFor({state: 'visible'});
  assert.match(await message.textContent(), /P2 y: "abc" is not a finite number/);
  assert.equal(await page.locator('.message:visible').count(), 1, 'one message, beside the table');
  assert.deepEqual((await pageState()).curves[0].points, typed);
  await page.locator('#add-point').click();
  assert.equal(await rows.count(), 5);
  await rows.nth(4).locator('button.remove-point').click();
  assert.equal(await rows.count(), 4);
  assert.deepEqual((await pageState()).curves[0].points, typed);

  assert.match(await paste('100,100 200,300; (300, 100)'), /Read 3 control points from the point list/);
  assert.deepEqual((await pageState()).curves[0].points, [[100, 100], [200, 300], [300, 100]]);
  assert.match(await paste('[[1.5, 2], [3, 4e2]]'), /Read 2/);
  assert.deepEqual((await pageState()).curves[0].points, [[1.5, 2], [3, 400]]);
  // Relative SVG path data, y down in the 800 x 600 drawing.
  await paste('m 100 500 c 100 -300 300 -300 400 0');
  assert.deepEqual((await pageState()).curves[0].points, [[100, 100], [200, 400], [400, 400], [500, 100]]);
  // Two segments taken as points: curves A and B.
  await page.locator('#paste-as').selectOption('points');
  assert.match(await paste('M100,500Q300 100 500 500L700-100'), /2 segments/);
  let state = await pageState();
  assert.deepEqual(state.curves.map((c) => c.points), [[[100, 100], [300, 500], [500, 100]], [[500, 100], [700, 700]]]);
  assert.equal(state.second, true);
  const pasted = state.curves.map((c) => c.points);
  // Path data the service cannot read is refused with its message; three segments are too many as points.
  for (const [text, pattern] of [['M 0 0 C 1 2 3', /could not read the path data: offset/],
                                 ['L 5 5', /could not read the path data/], ['1 2 3', /3 numbers/],
                                 ['M 0 0 H 10 V 10 Z', /4 segments|3 segments/]]) {
    assert.match(await paste(text), pattern, text);
    assert.deepEqual((await pageState()).curves.map((c) => c.points), pasted, `${text} changes nothing`);
  }

  await page.locator('#paste-as').selectOption('auto');
  await settle();

  // SVG export: exact path commands for degrees up to 3, in the same units as the paste.
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#download-svg').click()]);
  assert.equal(download.suggestedFilename(), 'bezier-playground.svg');
  const svg = readFileSync(await download.path(), 'utf8');
  assert.match(svg, /^<svg xmlns="http:\/\/www.w3.org\/2000\/svg" viewBox="0 0 800 600"/);
  assert.match(svg, /<rect width="800" height="600" fill="#ffffff"\/>/);
  assert.equal(svg.match(/<path id="curve-A" d="([^"]*)"/)[1], 'M 100 500 Q 300 100 500 500');
  assert.equal(svg.match(/<path id="curve-B" d="([^"]*)"/)[1], 'M 500 500 L 700 -100');
  assert.equal((svg.match(/<circle /g) ?? []).length, 5);

  // Undo and redo, by button and by key.
  await page.locator('#undo').click();
  state = await pageState();
  assert.deepEqual(state.curves[0].points, [[100, 100], [200, 400], [400, 400], [500, 100]]);
  assert.equal(state.second, false);
  await page.locator('#redo').click();
  assert.deepEqual((await pageState()).curves.map((c) => c.points), pasted);
  await page.locator('#scene').focus();
  await page.keyboard.press('Control+z');
  assert.equal((await pageState()).second, false);
  await page.keyboard.press('Control+Shift+Z');
  assert.deepEqual((await pageState()).curves.map((c) => c.points), pasted);
  assert.equal(await page.locator('#redo').isDisabled(), true, 'nothing left to redo');
  await settle();

  // The permalink opens the same drawing.
  await page.waitForFunction(() => location.hash === '#a=100,100;300,500;500,100&b=500,100;700,700&t0=0.37');
  const url = page.url();
  await page.locator('#copy-link').click();
  const shared = page.locator('#share-message');
  await shared.waitFor({state: 'visible'});
  assert.ok(/Link copied/.test(await shared.textContent()) || (await shared.textContent()).includes(url), 'the link is copied or shown');
  const other = await context.newPage();
  other.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(other);
  await other.goto(url);
  await settle(other);
  const opened = await pageState(other);
  assert.deepEqual(opened.curves.map((c) => c.points), pasted);
  assert.equal(opened.t0, 0.37);
  assert.equal(opened.second, true);
  assertSameAnswer((await pageAnswers(other)).intersections,
                   await api('/intersections', {curves: pasted.map((points) => ({points}))}), 'the link\'s intersections');
  await other.close();
});

// Two squares (drawing units, y up), each four line segments back to its start; their
// edges cross twice, away from every corner.
const kSquareA = [[100, 500], [300, 500], [300, 300], [100, 300]];
const kSquareB = [[200, 450], [450, 450], [450, 200], [200, 200]];
const squareSegments = (corners) => corners.map((p, k) => [p, corners[(k + 1) % corners.length]]);

/** Where two axis-aligned segments cross ({t, s, point}), or null: t and s as ratios of lengths. */
function axisCrossing([p0, p1], [q0, q1]) {
  const vertical = (a, b) => a[0] === b[0];
  if (vertical(p0, p1) === vertical(q0, q1)) return null;
  const [v0, v1, h0, h1] = vertical(p0, p1) ? [p0, p1, q0, q1] : [q0, q1, p0, p1];
  const point = [v0[0], h0[1]];
  const along = (a, b, k) => (point[k] - a[k]) / (b[k] - a[k]);
  const tv = along(v0, v1, 1);
  const th = along(h0, h1, 0);
  if (!(tv > 0 && tv < 1 && th > 0 && th < 1)) return null;
  return vertical(p0, p1) ? {t: tv, s: th, point} : {t: th, s: tv, point};
}

test('path mode: two pasted SVG paths intersected by segment, listed with t and s, marked; the link keeps them', async () => {
  const expected = [];
  squareSegments(kSquareA).forEach((a, i) => squareSegments(kSquareB).forEach((b, j) => {
    const hit = axisCrossing(a, b);
    if (hit) expected.push({segments: [i, j], ...hit});
  }));
  assert.equal(expected.length, 2);
  const before = await pageState();
  // Pasted as SVG data (y down): A absolute, B relative.
  const svgA = `M${[...kSquareA, kSquareA[0]].map(([x, y]) => `${x} ${kWorld.height - y}`).join(' L')}`;
  const closedB = [...kSquareB, kSquareB[0]];
  const svgB = `m${closedB[0][0]} ${kWorld.height - closedB[0][1]}` +
               closedB.slice(1).map((p, k) => ` l${p[0] - closedB[k][0]} ${closedB[k][1] - p[1]}`).join('');
  if (!(await page.locator('#show-second').isChecked())) await page.locator('#show-second').check();
  await page.locator('#editing input[value="0"]').check({force: true});
  assert.match(await paste(svgA), /4 segments/);
  await page.locator('#editing input[value="1"]').check({force: true});
  assert.match(await paste(svgB), /4 segments/);
  await settle();
  let state = await pageState();
  assert.deepEqual(state.curves.map((c) => c.path), [svgA, svgB]);
  assert.deepEqual(state.curves.map((c) => c.points), [[], []]);
  assert.ok(await page.locator('#path-note').isVisible());
  assert.ok(await page.locator('#points-table').isHidden());

  const worldPath = (corners) => `M${[...corners, corners[0]].map((p) => p.join(',')).join(' L')}`;
  const exact = await api('/intersections', {curves: [{path: worldPath(kSquareA)}, {path: worldPath(kSquareB)}]});
  assertSameAnswer((await pageAnswers()).intersections, exact, '/intersections of the paths');
  assert.equal(exact.intersections.length, expected.length);
  const items = page.locator('#intersections li[data-index]');
  assert.equal(await items.count(), expected.length);
  for (let k = 0; k < expected.length; ++k) {
    const hit = exact.intersections[k];
    const want = expected.find((e) => e.segments[0] === hit.segments[0] && e.segments[1] === hit.segments[1]);
    assert.ok(want, `API segments ${hit.segments} are a crossing of the squares`);
    assert.ok(Math.abs(hit.t - want.t) <= 1e-12 && Math.abs(hit.s - want.s) <= 1e-12, `t, s of ${hit.segments}`);
    const text = await items.nth(k).textContent();
    assert.match(text, new RegExp(`A segment ${want.segments[0]} × B segment ${want.segments[1]}: `));
    const [, , t, s, x, y] = numbersIn(text);
    assertClose(t, hit.t, `t of ${k}`);
    assertClose(s, hit.s, `s of ${k}`);
    assertClose(x, want.point[0], `x of ${k}`);
    assertClose(y, want.point[1], `y of ${k}`);
  }
  await page.mouse.move(5, 5);
  await settle();
  for (const {point} of expected) {
    assert.ok(near(await pixelAt(point), rgbOf('#c0392b')), `the crossing at (${point}) is marked`);
  }
  assert.deepEqual(await pageErrorsShown(), []);

  // No control points to add in path mode.
  await setMode('add');
  await clickWorld([600, 100]);
  assert.match(await page.locator('#canvas-message').textContent(), /Curve B is an SVG path: control-point editing is off/);
  assert.deepEqual((await pageState()).curves[1].points, []);

  // The link opens both paths.
  await page.waitForFunction((d) => decodeURIComponent(location.hash).includes(`pb=${d}`), svgB);
  const other = await context.newPage();
  other.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(other);
  await other.goto(page.url());
  await settle(other);
  assert.deepEqual((await pageState(other)).curves.map((c) => c.path), [svgA, svgB]);
  assertSameAnswer((await pageAnswers(other)).intersections, exact, 'the link\'s path intersections');
  await other.close();

  // Points mode: B's first segment becomes its control points, editable again.
  await page.locator('#points-mode').click();
  await settle();
  state = await pageState();
  assert.equal(state.curves[1].path, null);
  assert.deepEqual(state.curves[1].points, squareSegments(kSquareB)[0]);
  assert.ok(await page.locator('#points-table').isVisible());
  await clickWorld([600, 100]);
  assert.deepEqual((await pageState()).curves[1].points, [...squareSegments(kSquareB)[0], [600, 100]]);

  // Undo goes back through path mode to the drawing before the paths.
  for (let k = 0; k < 8 && JSON.stringify((await pageState()).curves) !== JSON.stringify(before.curves); ++k) {
    await page.locator('#undo').click();
  }
  state = await pageState();
  assert.deepEqual(state.curves, before.curves);
  assert.equal(state.active, before.active);
  await page.mouse.move(5, 5);
  await settle();
});

test('keyboard: the canvas takes focus, [ ] select, arrows move, + adds, Delete removes', async () => {
  const canvas = page.locator('#scene');
  await canvas.focus();
  assert.equal(await page.evaluate(() => document.activeElement.id), 'scene');
  const undoDepth = (await page.evaluate(() => window.playground.history())).undo;
  await page.keyboard.press(']');
  await page.keyboard.press(']');
  assert.deepEqual((await pageState()).selected, {curve: 0, index: 1});
  for (let k = 0; k < 3; ++k) await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowUp');
  await page.keyboard.press('ArrowDown');
  assert.deepEqual((await pageState()).curves[0].points, [[100, 100], [303, 509], [500, 100]]);
  assert.match(await page.locator('#canvas-status').textContent(), /Selected P1 at \(303, 509\)/);
  assert.equal((await page.evaluate(() => window.playground.history())).undo, undoDepth + 1, 'one undo step for the moves');
  await page.keyboard.press('+');
  let state = await pageState();
  assert.deepEqual(state.curves[0].points, [[100, 100], [303, 509], [402, 305], [500, 100]], 'halfway to the next point');
  assert.deepEqual(state.selected, {curve: 0, index: 2});
  await page.keyboard.press('Delete');
  state = await pageState();
  assert.deepEqual(state.curves[0].points, [[100, 100], [303, 509], [500, 100]]);
  await page.keyboard.press('Control+z');
  assert.equal((await pageState()).curves[0].points.length, 4);
  await page.keyboard.press('Control+z');
  await page.keyboard.press('Control+z');
  assert.deepEqual((await pageState()).curves[0].points, [[100, 100], [300, 500], [500, 100]]);
  await settle();
  // The table follows, its row of the selected point marked.
  assert.equal(await page.locator('#points-table tbody tr').count(), 3);
  const {selected} = await pageState();
  assert.equal(await page.locator('#points-table tbody tr.selected').getAttribute('data-index'), String(selected.index));
  const drawn = (await pageAnswers()).curves[0].evaluate;
  assert.deepEqual(drawn, await api('/evaluate', {points: [[100, 100], [300, 500], [500, 100]], samples: drawn.results.length}));
});

test('a 1280 x 800 screen holds the main controls; a refused request is shown once, beside the control points', async () => {
  const laptop = await context.newPage();
  laptop.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(laptop);
  await laptop.setViewportSize({width: 1280, height: 800});
  // A link with a curve past the degree limit: every request for it fails alike.
  const seven = [[100, 100], [200, 300], [300, 100], [400, 300], [500, 100], [600, 300], [700, 100]];
  await laptop.goto(`${baseUrl}/#a=${seven.map((p) => p.join(',')).join(';')}&t0=0.5`);
  await settle(laptop);
  // The curve is sampled alone first (the page has not drawn one of 7 points yet): one refusal, nothing else sent.
  const failed = await pageErrorsShown(laptop);
  assert.deepEqual(failed.map((e) => [e.route, e.status]), [['/evaluate', 422]], 'one request, refused');
  const listed = laptop.locator('#points-errors li[data-status="422"]');
  assert.equal(await listed.count(), 1, 'one entry for one cause');
  assert.match(await listed.textContent(), new RegExp(`limit of ${kMaxDegree}`));
  assert.match(await listed.textContent(), /Asked for: curve A\./);
  assert.equal(await laptop.locator('#errors li').count(), 0, 'nothing in the general list');
  // The view says why there is no curve, and shows the link's control points.
  const said = laptop.locator('#canvas-message');
  await said.waitFor({state: 'visible'});
  assert.match(await said.textContent(), new RegExp(`degree at most ${kMaxDegree}.*curve A has 7, so only its control points are drawn`));
  const dots = await pixelsAt(seven, 0, laptop);
  assert.ok(dots.every((px) => px[3] > 0), 'every control point of the link is drawn');
  const sentBefore = failed.length;
  await laptop.locator('#t0-number').fill('0.4');
  await laptop.locator('#t0-number').press('Tab');
  await settle(laptop);
  assert.equal((await pageErrorsShown(laptop)).length, 0, 'known past the limit: nothing more is asked about the curve');
  assert.ok(sentBefore > 0);

  // A link that cannot be read says so beside the canvas and changes nothing.
  await laptop.goto(`${baseUrl}/#a=1,2;3&t0=0.5`);
  await laptop.locator('#canvas-message').waitFor({state: 'visible'});
  assert.match(await laptop.locator('#canvas-message').textContent(), /could not be read: point 1 of a/);
  assert.equal((await pageState(laptop)).curves[0].points.length, 7);
  await laptop.goto(`${baseUrl}/#a=${kFour.map((p) => p.join(',')).join(';')}&t0=0.5`);
  await settle(laptop);
  assert.deepEqual((await pageState(laptop)).curves[0].points, kFour);
  assert.equal(await laptop.locator('#points-errors li').count(), 0);
  for (const selector of ['.toolbar', '#scene', '#t0-range', '#t0-number', '#animate', '.checks', '#points-table', '#add-point']) {
    const box = await laptop.locator(selector).boundingBox();
    assert.ok(box.y >= 0 && box.y + box.height <= 800 && box.x + box.width <= 1280, `${selector} fits: ${JSON.stringify(box)}`);
  }
  const widths = await laptop.evaluate(() => ({page: document.documentElement.scrollWidth, view: window.innerWidth}));
  assert.ok(widths.page <= widths.view);
  await laptop.close();
});

test('phone width: no sideways scrolling, and a tap adds a point', async () => {
  const phone = await context.newPage();
  phone.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(phone);
  await phone.setViewportSize({width: 390, height: 844});
  await phone.goto(baseUrl + '/#a=&t0=0.5');
  await settle(phone);
  const widths = await phone.evaluate(() => ({page: document.documentElement.scrollWidth, view: window.innerWidth}));
  assert.ok(widths.page <= widths.view, `page ${widths.page} px wide in a ${widths.view} px viewport`);
  const box = await phone.locator('#scene').boundingBox();
  assert.ok(box.width <= 390 && box.width >= 300, `canvas ${box.width} px wide`);
  for (const w of [[100, 100], [400, 500], [700, 100]]) {
    const [x, y] = await client(w, phone);
    await phone.touchscreen.tap(x, y);
  }
  await settle(phone);
  const points = (await pageState(phone)).curves[0].points;
  assert.equal(points.length, 3);
  // A CSS pixel is about two world units here, so a tap lands within a unit or two.
  points.forEach((p, k) => assert.ok(Math.abs(p[0] - [100, 400, 700][k]) <= 2 && Math.abs(p[1] - [100, 500, 100][k]) <= 2));
  assert.ok((await pageAnswers(phone)).curves[0].evaluate, 'the curve is drawn');

  // No two labels overlap, on the canvas (the crowded construction of a loop crossed by
  // a second curve) or on the page.
  await phone.goto(`${baseUrl}/#a=250,100;750,560;50,560;550,100&b=${kCrossing.map((p) => p.join(',')).join(';')}&t0=0.37`);
  // A new fragment on the same page is a same-document navigation: the page is idle until
  // it has read the fragment, so wait for the state first, then for its answers.
  await phone.waitForFunction(() => {
    const state = window.playground.state();
    return state.curves.length >= 2 && state.curves[0].points.length === 4 && state.curves[0].points[0][0] === 250;
  }, null, {timeout: kTimeout});
  await settle(phone);
  const {placed, marks} = await phone.evaluate(() => window.playground.labels());
  const canvasBox = await phone.locator('#scene').boundingBox();
  assert.ok(placed.length >= 12, `${placed.length} labels placed`);
  const overlapping = (a, b) => a.x < b.x + b.w - 0.5 && b.x < a.x + a.w - 0.5 && a.y < b.y + b.h - 0.5 && b.y < a.y + a.h - 0.5;
  for (const [k, a] of placed.entries()) {
    assert.ok(a.x >= 0 && a.y >= 0 && a.x + a.w <= canvasBox.width && a.y + a.h <= canvasBox.height, `${a.text} inside`);
    for (const b of placed.slice(k + 1)) assert.ok(!overlapping(a, b), `canvas labels ${a.text} and ${b.text} overlap`);
  }
  // No label covers a mark: every control point, B(t0) and construction point is kept clear,
  // each of them checked here from the state and the answers, not from the page's list.
  const crowded = await pageState(phone);
  const crowdedAnswers = await pageAnswers(phone);
  const markPoints = [...crowded.curves[0].points, ...crowded.curves[1].points, crowdedAnswers.polar.curve_point,
                      ...crowdedAnswers.casteljau.levels.slice(1, -1).flat()];
  assert.ok(marks.length >= markPoints.length, 'the page keeps each mark clear');
  for (const p of markPoints) {
    const x = p[0] * canvasBox.width / kWorld.width;
    const y = (kWorld.height - p[1]) * canvasBox.height / kWorld.height;
    const disc = {x: x - 3, y: y - 3, w: 6, h: 6};
    for (const a of placed) assert.ok(!overlapping(a, disc), `label ${a.text} covers the mark at (${p})`);
  }
  // A tight row of points: the construction's names would stand in a row over it, so they are left
  // out (each level keeps its colour, the legend names it) and nothing placed overlaps.
  const row = [...Array(kMaxDegree + 1).keys()].map((k) => [300 + 20 * k, k % 2 ? 320 : 300]);
  await phone.goto(`${baseUrl}/#a=${row.map((p) => p.join(',')).join(';')}&t0=0.5`);
  await phone.waitForFunction(() => window.playground.state().curves[0].points.length === 6 && !window.playground.state().second,
                              null, {timeout: kTimeout});
  await settle(phone);
  const tight = await phone.evaluate(() => window.playground.labels());
  assert.ok(!tight.placed.some((b) => /^b/.test(b.text)), 'no construction name placed in the row');
  assert.ok(tight.dropped.filter((text) => /^b/.test(text)).length >= kMaxDegree, 'they are left out');
  for (const [k, a] of tight.placed.entries()) {
    for (const b of tight.placed.slice(k + 1)) assert.ok(!overlapping(a, b), `canvas labels ${a.text} and ${b.text} overlap`);
  }
  const boxes = await phone.locator('h1, .lede, .segmented legend, .segmented span, .actions > button, select, .status, ' +
                                    '.t0-row > *, .checks label, summary, h2, #points-table th, #points-table input')
      .evaluateAll((nodes) => nodes.map((n) => {
        const r = n.getBoundingClientRect();
        return {what: `${n.tagName} ${n.id || n.className} ${n.textContent.trim().slice(0, 20)}`, x: r.x, y: r.y, w: r.width, h: r.height};
      }).filter((b) => b.w > 0 && b.h > 0));
  assert.ok(boxes.length > 40);
  for (const [k, a] of boxes.entries()) {
    for (const b of boxes.slice(k + 1)) assert.ok(!overlapping(a, b), `${a.what} and ${b.what} overlap`);
  }
  await phone.close();
});

/** The signed area of a polygon (shoelace), counter-clockwise positive. */
const shoelace = (corners) => corners.reduce((sum, p, k) => {
  const q = corners[(k + 1) % corners.length];
  return sum + (p[0] * q[1] - q[0] * p[1]) / 2;
}, 0);

/** Distance from p to the segment [a, b]. */
function segmentDistance(p, [a, b]) {
  const d = [b[0] - a[0], b[1] - a[1]];
  const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1])));
  return Math.hypot(p[0] - a[0] - t * d[0], p[1] - a[1] - t * d[1]);
}

const emptyDrawing = async () => {
  await page.goto(baseUrl + '/#a=&t0=0.5');
  await page.waitForFunction(() => window.playground.state().curves[0].points.length === 0 && !window.playground.state().curves[0].path);
  await settle();
};

test('path mode: the issue\'s Z path is read by /segments and drawn with its area, length, box, loops and nearest point', async () => {
  await emptyDrawing();
  await page.locator('#paste-as').selectOption('auto');
  // Every command SVG has is read (by /segments): H, V, S, T and A give segments too.
  assert.match(await paste('M 100 500 H 300'), /Read 2 control points from SVG path data/);
  assert.deepEqual((await pageState()).curves[0].points, [[100, 100], [300, 100]]);
  assert.match(await paste('M 100 500 Q 200 300 300 500 T 500 500'), /2 segments/);
  await settle();
  assert.deepEqual((await pageAnswers()).curves[0].path.segments[1], [[300, 100], [400, -100], [500, 100]], 'T reflects Q\'s control point');
  // A square in SVG units (y down) closed by Z: the drawing has it at y = 600 - y.
  assert.match(await paste('M 200 100 L 600 100 L 600 500 L 200 500 Z'), /4 segments/);
  await settle();
  const corners = [[200, 500], [600, 500], [600, 100], [200, 100]];
  const edges = corners.map((p, k) => [p, corners[(k + 1) % 4]]);
  const answers = await pageAnswers();
  const path = answers.curves[0].path;
  assert.deepEqual(path.segments, edges, 'four lines, the last the closing line of Z');
  assert.deepEqual(path.closing, [false, false, false, true]);
  assert.deepEqual(await pageErrorsShown(), []);
  // Area (Green's theorem = the shoelace for lines), length, box: the path routes' answers, shown.
  assert.equal(answers.curves[0].loopArea.closed_area, shoelace(corners));
  assertClose(numbersIn(await page.locator('#value-area').textContent())[0], shoelace(corners), 'enclosed area');
  assertClose(answers.measure.length.length, 1600, 'length');
  assertClose(numbersIn(await page.locator('#value-length').textContent())[0], 1600, 'length shown');
  assert.deepEqual([answers.measure.bounds.min, answers.measure.bounds.max], [[200, 100], [600, 500]]);
  assert.deepEqual(numbersIn(await page.locator('#value-box').textContent()), [200, 100, 600, 500]);
  assert.equal(answers.curves[0].selfIntersections.intersections.length, 0);
  // Drawn: each edge's middle in curve A's colour.
  for (const [a, b] of edges) {
    const px = await pixelAt([(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]);
    assert.ok(near(px, rgbOf('#1f6fd1'), 60), `edge ${a} to ${b} drawn: ${px}`);
  }
  // The nearest point of the path to the pointer (/nearest with the path).
  const [x, y] = await client([400, 330]);
  await page.mouse.move(x, y);
  const result = await page.waitForFunction(() => {
    const n = window.playground.nearest();
    return !n.inFlight && n.result && n;
  }, null, {timeout: kTimeout}).then((h) => h.jsonValue());
  const {target, answer} = result.result;
  assertClose(answer.distance, Math.min(...edges.map((e) => segmentDistance(target, e))), 'distance to the square');
  assert.match(await page.locator('#value-nearest').textContent(), /on segment \d/);
  await page.mouse.move(5, 5);

  // A bow tie: the path crosses itself once, at the middle; its loops are listed.
  assert.match(await paste('M 200 100 L 600 500 L 600 100 L 200 500 Z'), /4 segments/);
  await settle();
  const bow = await pageAnswers();
  const self = bow.curves[0].selfIntersections.intersections;
  assert.equal(self.length, 1);
  self[0].point.forEach((v, k) => assert.ok(Math.abs(v - [400, 300][k]) <= 1e-9 * 800));
  assert.equal(await page.locator('#loops li[data-kind=self]').count(), 1);
  assert.ok(near(await pixelAt([400, 300]), rgbOf('#c0392b')), 'the crossing is marked');
  assert.equal(bow.curves[0].loopArea.loops.length, await page.locator('#loops li[data-curve=A]:not([data-kind])').count());
});

test('the permalink keeps the layers shown', async () => {
  await page.locator('#show-polar').uncheck();
  await page.locator('#show-box').uncheck();
  await page.waitForFunction(() => location.hash.includes('hide=polar,box'));
  const other = await context.newPage();
  other.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(other);
  await other.goto(page.url());
  await settle(other);
  const opened = await pageState(other);
  assert.equal(opened.show.polar, false);
  assert.equal(opened.show.box, false);
  assert.equal(opened.show.curve, true);
  assert.equal(await other.locator('#show-polar').isChecked(), false);
  assert.equal(await other.locator('#show-box').isChecked(), false);
  assert.equal(opened.curves[0].path, (await pageState()).curves[0].path, 'and the path');
  await other.close();
  await page.locator('#show-polar').check();
  await page.locator('#show-box').check();
  await page.waitForFunction(() => !location.hash.includes('hide='));
});

test('regions: the operation\'s result filled, segments coloured by source, the winding numbers under the pointer', async () => {
  await page.locator('#views input[value=regions]').check({force: true});
  await settle();
  assert.equal((await pageState()).view, 'regions');
  assert.ok(await page.locator('#regions-panel').isVisible());
  assert.ok(await page.locator('#t0-range').isHidden(), 'the curves\' controls are out of the way');
  await page.locator('#region-examples').selectOption('squares');
  await settle();
  // Squares A (150..450 both ways) and B (x 320..650, y 80..370 in the drawing, y up).
  const a = [[150, 450], [450, 450], [450, 150], [150, 150]];
  const b = [[320, 370], [650, 370], [650, 80], [320, 80]];
  const areaA = Math.abs(shoelace(a));
  const areaB = Math.abs(shoelace(b));
  const common = (450 - 320) * (370 - 150);
  const expected = {union: areaA + areaB - common, intersection: common, difference: areaA - common,
                    xor: areaA + areaB - 2 * common};
  for (const op of ['intersection', 'difference', 'xor', 'union']) {
    await page.locator('#region-op').selectOption(op);
    await settle();
    const answers = await pageAnswers();
    assert.equal(answers.boolean.area, expected[op], `${op}: area`);
    assertClose(numbersIn(await page.locator('#region-values dd[data-term=area]').textContent())[0], expected[op], `${op} shown`);
    // Every result segment is a piece of the shape it names.
    for (const segment of answers.boolean.segments) {
      const box = segment.source === 'a' ? a : b;
      const xs = box.map((p) => p[0]);
      const ys = box.map((p) => p[1]);
      for (const p of segment.points) {
        const onEdge = (p[0] === Math.min(...xs) || p[0] === Math.max(...xs)) || (p[1] === Math.min(...ys) || p[1] === Math.max(...ys));
        assert.ok(onEdge, `${op}: ${p} lies on the edge of shape ${segment.source}`);
      }
    }
  }
  const answers = await pageAnswers();
  assert.deepEqual(await pageErrorsShown(), []);
  // Filled where the union is, not elsewhere; each segment in its source's colour.
  assert.ok((await pixelAt([200, 400]))[3] > 0, 'A alone is in the union');
  assert.ok((await pixelAt([600, 120]))[3] > 0, 'B alone is in the union');
  assert.equal((await pixelAt([720, 540]))[3], 0, 'outside both: nothing drawn');
  for (const source of ['a', 'b']) {
    const segment = answers.boolean.segments.find((s) => s.source === source && s.degree === 1 &&
        Math.hypot(s.points[1][0] - s.points[0][0], s.points[1][1] - s.points[0][1]) > 60);
    const middle = [(segment.points[0][0] + segment.points[1][0]) / 2, (segment.points[0][1] + segment.points[1][1]) / 2];
    assert.ok(near(await pixelAt(middle), rgbOf(source === 'a' ? '#1f6fd1' : '#d35400'), 60), `a segment from ${source} in its colour`);
  }
  // The point under the pointer: inside both squares; winding numbers by the orientation of each (y up).
  const [x, y] = await client([400, 300]);
  await page.mouse.move(x, y);
  const readout = page.locator('#winding');
  await page.waitForFunction(() => /result: winding/.test(document.getElementById('winding').textContent));
  const text = await readout.textContent();
  const sign = (corners) => Math.sign(shoelace(corners));
  assert.match(text, new RegExp(`A: winding ${sign(a)}, inside; B: winding ${sign(b)}, inside; result: winding 1, inside`));
  // The picture of the regions view for the README (beside the main one): the union, the pointer in both squares.
  if (screenshotPath) await page.screenshot({path: screenshotPath.replace(/(\.png)?$/, '-regions.png')});
  await page.mouse.move(5, 5);

  // The link opens the same regions.
  await page.waitForFunction(() => location.hash.includes('view=regions') && location.hash.includes('op=union'));
  const other = await context.newPage();
  other.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(other);
  await other.goto(page.url());
  await settle(other);
  assert.deepEqual((await pageState(other)).regions, (await pageState()).regions);
  assert.equal((await pageAnswers(other)).boolean.area, expected.union);
  await other.close();

  // Pasted shapes, arcs included: a disc of radius 100 (two arcs) cut by the half-plane right of its centre.
  await page.locator('#region-op').selectOption('intersection');
  await page.locator('#region-a').fill('M 300 300 A 100 100 0 1 1 500 300 A 100 100 0 1 1 300 300 Z');
  await page.locator('#region-b').fill('M 400 100 H 700 V 500 H 400 Z');
  await page.locator('#region-form button[type=submit]').click();
  await page.waitForFunction(() => window.playground.state().regions.a.includes('A 100 100'));
  await settle();
  const half = await pageAnswers();
  // The arcs keep within 1e-6 of the radius (the default arc_tolerance) of the circle, so the area is within
  // the half circle's length times that band.
  assert.ok(Math.abs(half.boolean.area - Math.PI * 100 * 100 / 2) <= Math.PI * 100 * 1e-6 * 100, `half a disc: ${half.boolean.area}`);
  assert.ok(half.boolean.segments.some((s) => s.source === 'a' && s.degree === 3) &&
            half.boolean.segments.some((s) => s.source === 'b' && s.degree === 1), 'arcs from A, the cut from B');
  // Path data the service cannot read: its refusal is listed, the view waits for a readable shape.
  await page.locator('#region-b').fill('M 400 100 H');
  await page.locator('#region-form button[type=submit]').click();
  await page.waitForFunction(() => window.playground.state().regions.b === 'M 400 100 H');
  await settle();
  const refused = await pageErrorsShown();
  assert.deepEqual(refused.map((e) => [e.route, e.status]), [['/segments', 422]]);
  assert.equal((await pageAnswers()).boolean, null);
  await page.locator('#region-op').selectOption('union');

  // Simplify a glyph whose strokes overlap: the result has no crossing left (its area is less than the sum).
  await page.locator('#region-examples').selectOption('glyph');
  await settle();
  const glyph = await pageAnswers();
  assert.equal((await pageState()).regions.op, 'simplify');
  assert.ok(glyph.boolean.contours.length >= 1);
  assert.deepEqual(await pageErrorsShown(), []);
  const self = await api('/intersections', {curves: [{path: glyph.boolean.path}]});
  assert.equal(self.intersections.length, 0, 'the simplified outline does not cross itself');
});

test('outline: the flattened path\'s vertices on the path and the offset, following the sliders', async () => {
  await page.locator('#views input[value=outline]').check({force: true});
  await settle();
  assert.ok(await page.locator('#outline-panel').isVisible());
  const state = await pageState();
  const answers = await pageAnswers();
  const read = await api('/segments', {path: state.outline.path});
  assert.deepEqual(answers.path.segments, read.segments.map((s) => s.points.map(([px, py]) => [px, kWorld.height - py])));
  const onPath = (vertices, polylines, segments) => polylines.forEach((line, k) => line.forEach((p, j) => {
    const v = vertices[k][j];
    casteljau(segments[v.segment], v.t).forEach((c, axis) => assert.ok(Math.abs(c - p[axis]) <= 1e-9 * 800, `vertex ${k}.${j} on the path`));
  }));
  onPath(answers.flatten.vertices, answers.flatten.polylines, answers.path.segments);
  const coarse = answers.flatten.count;
  assert.match(await page.locator('#outline-values dd[data-term=vertices]').textContent(), new RegExp(`^${coarse} in`));
  const vertex = answers.flatten.polylines[0][Math.floor(answers.flatten.polylines[0].length / 2)];
  assert.ok(near(await pixelAt(vertex), rgbOf('#8a3fd1'), 50), 'a vertex is marked');
  // The offset: its points at |d| from the path, within the tolerance.
  // Each cubic's ends and middle lie at |d| from the segment it stands for (measured by /nearest on that segment).
  const checkOffset = async (offset, d, tolerance) => {
    assert.ok(offset.segments.length >= answers.path.segments.length);
    for (const s of offset.segments) {
      const targets = [s.points[0], casteljau(s.points, 0.5), s.points[3]];
      const nearest = await api('/nearest', {points: answers.path.segments[s.source_segment], targets});
      nearest.results.forEach((r) => assert.ok(Math.abs(r.distance - Math.abs(d)) <= tolerance + 1e-9 * 800,
                                               `offset of segment ${s.source_segment} at ${r.distance}, not ${Math.abs(d)}`));
    }
  };
  await checkOffset(answers.offset, state.outline.distance, state.outline.tolerance);
  // The sliders: a finer tolerance, more vertices; distance 0, no offset; then the other side.
  const slide = async (id, value) => page.locator(id).evaluate((input, v) => {
    input.value = v;
    input.dispatchEvent(new Event('input', {bubbles: true}));
  }, String(value));
  await slide('#tolerance', -1.5);
  await settle();
  const fine = await pageAnswers();
  assert.equal((await pageState()).outline.tolerance, 0.0316);
  assert.ok(fine.flatten.count > coarse, `${fine.flatten.count} vertices at 0.0316 against ${coarse}`);
  onPath(fine.flatten.vertices, fine.flatten.polylines, fine.path.segments);
  assert.equal(await page.locator('#tolerance-value').textContent(), '0.0316');
  await slide('#distance', 0);
  await settle();
  assert.equal((await pageAnswers()).offset, null);
  await slide('#distance', 45);
  await settle();
  const outside = await pageAnswers();
  await checkOffset(outside.offset, 45, 0.0316);
  assert.deepEqual(await pageErrorsShown(), []);
  await page.waitForFunction(() => location.hash.includes('view=outline') && location.hash.includes('d=45'));
  const other = await context.newPage();
  other.on('pageerror', (e) => pageErrors.push(e.message));
  recordPolicyViolations(other);
  await other.goto(page.url());
  await settle(other);
  assert.deepEqual((await pageState(other)).outline, (await pageState()).outline);
  assert.equal(await other.locator('#distance').inputValue(), '45');
  await other.close();

  // Stroking: the /stroke route's outline, read back by /segments.
  await page.locator('#stroke-on').check();
  await settle();
  const stroked = await pageAnswers();
  const {tolerance} = (await pageState()).outline;
  const probe = await fetch(baseUrl + '/stroke', {
    method: 'POST', headers: {'Content-Type': 'application/json'},
    body: JSON.stringify({path: stroked.path.data, width: 40, join: 'round', cap: 'round', tolerance}),
  });
  const strokeShown = await page.locator('#outline-values dd[data-term=stroke]').textContent();
  assert.equal(probe.status, 200, 'the service strokes the path');
  const outlineRead = await api('/segments', {path: (await probe.json()).path});
  assert.deepEqual(stroked.stroke.segments, outlineRead.segments.map((s) => s.points));
  assert.match(strokeShown, /width 40, round joins, round caps/);
  assert.deepEqual(await pageErrorsShown(), []);
  assert.ok(stroked.flatten && stroked.offset, 'flattening and offset are drawn all the same');
  await page.waitForFunction(() => location.hash.includes('sw=40&join=round&cap=round'));
  await page.locator('#stroke-on').uncheck();
  await settle();
  assert.deepEqual(await pageErrorsShown(), []);
  await page.locator('#views input[value=curves]').check({force: true});
  await settle();
});

test('no script errors on the page, and nothing blocked by its security policy', () => {
  assert.deepEqual(pageErrors, []);
  assert.deepEqual(policyViolations, []);
});
