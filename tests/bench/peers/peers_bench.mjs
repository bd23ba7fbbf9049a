// The JavaScript peers on the shapes of the C++ region and outline benchmarks: Skia's PathOps
// and stroker (npm canvaskit-wasm: WebAssembly, float32 coordinates) and Paper.js (npm paper:
// booleans, flatten; npm paperjs-offset: offset). The shapes and our answers come from
// bezier_peer_shapes (tests/bench/peers/shapes_dump.cpp), so every library runs on the same
// doubles (Skia rounds them to float32 on input).
//
//   npm ci --prefix tests/bench/peers
//   node tests/bench/peers/peers_bench.mjs build/tests/bezier_peer_shapes [section...]
//
// Sections (all when none is named):
//   booleans  time per pair of union and intersection on the pairs of glyph-like outlines
//             (20, 50 and 100 cubics, 8 pairs each), Skia and Paper.js interleaved round by
//             round; the largest relative difference of each result's area from ours.
//   cases     the region hard cases: for each case and operation, the area against ours and
//             the sample points where membership in the peer's result differs from the
//             definition (tests/bench/region_case_truth.hpp).
//   flatten   chords of Paper.js's flatten against ours at the same verified maximum error.
//   offset    segments of Skia's stroker and paperjs-offset against our offset cubics at the
//             same verified maximum error.
//   stroke    the stroke outline of the glyph outlines (width 0.04): segments of Skia's stroker and paperjs-offset's
//             offsetStroke against our /stroke kernel at the same verified maximum error, and
//             CPU time per stroked shape of Skia's stroker and ours (bezier_peer_shapes
//             stroke-time, a child process) alternating round by round.
// Option --rounds N (default 5): timing rounds; each round runs every timed configuration once
// for at least --min-ms milliseconds of CPU time (default 200), in an order rotated each round.
//
// Verified error (flatten, offset): measured here, independently of every library, by dense
// sampling. A curve is sampled at 1024 points per segment (`kDense`); distances are to the
// chords of the other side's dense samples (point-to-segment, found through a uniform grid),
// both ways (the Hausdorff distance, up to the sagitta of the dense chords, about
// curvature x (segment length / 1024)^2 / 8). For an offset at distance d, a sample of the
// peer's outline is off by |distance to the source outline - d|, and a sample B(t) + d N(t) of
// the exact offset is off by its distance to the peer's outline; the error is the larger of
// the two maxima.

import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';

const require = createRequire(import.meta.url);
const paper = require('paper');
const CanvasKitInit = require('canvaskit-wasm');
const PaperOffset = require('paperjs-offset');

const args = process.argv.slice(2);
const dumpBinary = args.shift();
if (!dumpBinary) {
  console.error('usage: node peers_bench.mjs <bezier_peer_shapes> [booleans|cases|flatten|offset|stroke ...] [--rounds N] [--min-ms M]');
  process.exit(2);
}
const option = (name, fallback) => {
  const i = args.indexOf(name);
  if (i < 0) return fallback;
  const value = Number(args[i + 1]);
  args.splice(i, 2);
  return value;
};
const rounds = option('--rounds', 5);
const minMs = option('--min-ms', 200);
const sections = args.length ? args : ['booleans', 'cases', 'flatten', 'offset', 'stroke'];

const CK = await CanvasKitInit();
paper.setup(new paper.Size(1000, 1000));
const shapes = JSON.parse(execFileSync(dumpBinary, { maxBuffer: 1 << 30 }).toString());

const kDense = 1024;

// ---- shapes in each library ----

const pointsOf = (flat) => {
  const out = [];
  for (let i = 0; i < flat.length; i += 2) out.push([flat[i], flat[i + 1]]);
  return out;
};

/** Skia path of a closed outline of cubics (control points P0 .. P3n, P3n == P0). */
function skiaOutline(flat) {
  const p = pointsOf(flat);
  const cmds = [CK.MOVE_VERB, p[0][0], p[0][1]];
  for (let k = 0; k + 3 < p.length; k += 3) {
    cmds.push(CK.CUBIC_VERB, p[k + 1][0], p[k + 1][1], p[k + 2][0], p[k + 2][1], p[k + 3][0], p[k + 3][1]);
  }
  cmds.push(CK.CLOSE_VERB);
  return CK.Path.MakeFromCmds(cmds);
}

/** Paper.js closed path of the same cubics: segment k at P3k with handles to P3k+1, P3k-1. */
function paperOutline(flat) {
  const p = pointsOf(flat);
  const n = (p.length - 1) / 3;
  const segments = [];
  for (let k = 0; k < n; ++k) {
    const at = p[3 * k];
    const before = p[3 * k === 0 ? p.length - 2 : 3 * k - 1];
    const after = p[3 * k + 1];
    segments.push(new paper.Segment(new paper.Point(at[0], at[1]),
      new paper.Point(before[0] - at[0], before[1] - at[1]),
      new paper.Point(after[0] - at[0], after[1] - at[1])));
  }
  return new paper.Path({ segments, closed: true, insert: false });
}

/** The cubics of a closed outline, each [[x, y] x 4]. */
function outlineCubics(flat) {
  const p = pointsOf(flat);
  const cubics = [];
  for (let k = 0; k + 3 < p.length; k += 3) cubics.push([p[k], p[k + 1], p[k + 2], p[k + 3]]);
  return cubics;
}

// ---- areas (Green's theorem on Bézier control points) ----

function binomial(m, k) {
  let r = 1;
  for (let q = 1; q <= k; ++q) r = (r * (m - k + q)) / q;
  return r;
}

/** (1/2) ∫ x y' - y x' over a Bézier curve of any degree (region_case_truth.hpp's formula). */
function greenArea(p) {
  const n = p.length - 1;
  let sum = 0;
  for (let i = 0; i <= n; ++i) {
    for (let j = 0; j < n; ++j) {
      const w = (binomial(n, i) * binomial(n - 1, j)) / (2 * n * binomial(2 * n - 1, i + j));
      sum += w * n * (p[i][0] * (p[j + 1][1] - p[j][1]) - p[i][1] * (p[j + 1][0] - p[j][0]));
    }
  }
  return 0.5 * sum;
}

/** The segments of a Skia path as control point lists, from toCmds (conics as [..., weight]). */
function skiaSegments(path) {
  const cmds = path.toCmds();
  const out = [];
  let start = null;
  let last = null;
  for (let i = 0; i < cmds.length;) {
    const verb = cmds[i++];
    if (verb === CK.MOVE_VERB) {
      if (last && start && (last[0] !== start[0] || last[1] !== start[1])) out.push({ points: [last, start] });
      start = last = [cmds[i], cmds[i + 1]];
      i += 2;
    } else if (verb === CK.LINE_VERB) {
      const q = [cmds[i], cmds[i + 1]];
      out.push({ points: [last, q] });
      last = q;
      i += 2;
    } else if (verb === CK.QUAD_VERB) {
      const q = [[cmds[i], cmds[i + 1]], [cmds[i + 2], cmds[i + 3]]];
      out.push({ points: [last, ...q] });
      last = q[1];
      i += 4;
    } else if (verb === CK.CONIC_VERB) {
      const q = [[cmds[i], cmds[i + 1]], [cmds[i + 2], cmds[i + 3]]];
      out.push({ points: [last, ...q], weight: cmds[i + 4] });
      last = q[1];
      i += 5;
    } else if (verb === CK.CUBIC_VERB) {
      const q = [[cmds[i], cmds[i + 1]], [cmds[i + 2], cmds[i + 3]], [cmds[i + 4], cmds[i + 5]]];
      out.push({ points: [last, ...q] });
      last = q[2];
      i += 6;
    } else if (verb === CK.CLOSE_VERB) {
      if (last && start && (last[0] !== start[0] || last[1] !== start[1])) out.push({ points: [last, start] });
      last = start;
    } else {
      throw new Error(`unknown verb ${verb}`);
    }
  }
  if (last && start && (last[0] !== start[0] || last[1] !== start[1])) out.push({ points: [last, start] });
  return out;
}

/** A point of a segment (Bézier of any degree, or a rational quadratic with `weight`). */
function segmentPoint(s, t) {
  const p = s.points;
  if (s.weight !== undefined) {
    const w = s.weight, u = 1 - t;
    const b0 = u * u, b1 = 2 * u * t * w, b2 = t * t;
    const d = b0 + b1 + b2;
    return [(b0 * p[0][0] + b1 * p[1][0] + b2 * p[2][0]) / d, (b0 * p[0][1] + b1 * p[1][1] + b2 * p[2][1]) / d];
  }
  const q = p.map((v) => [v[0], v[1]]);
  for (let r = q.length - 1; r > 0; --r) {
    for (let i = 0; i < r; ++i) {
      q[i][0] += t * (q[i + 1][0] - q[i][0]);
      q[i][1] += t * (q[i + 1][1] - q[i][1]);
    }
  }
  return q[0];
}

/** Signed area of a Skia path: Green's theorem, conics by 4096-point midpoint sums. */
function skiaArea(path) {
  let sum = 0;
  for (const s of skiaSegments(path)) {
    if (s.weight === undefined) {
      sum += greenArea(s.points);
    } else {
      let prev = segmentPoint(s, 0);
      for (let k = 1; k <= 4096; ++k) {
        const next = segmentPoint(s, k / 4096);
        sum += 0.5 * (prev[0] * next[1] - prev[1] * next[0]);
        prev = next;
      }
    }
  }
  return sum;
}

/** The contours of a Skia path, each a list of segments. */
function skiaContours(path) {
  const contours = [];
  let current = null;
  const cmds = path.toCmds();
  // Split the verb stream at each move, then read each part's segments.
  let part = [];
  const flush = () => {
    if (part.length) {
      const sub = CK.Path.MakeFromCmds(part);
      current = skiaSegments(sub);
      sub.delete();
      if (current.length) contours.push(current);
    }
    part = [];
  };
  const sizes = { [CK.MOVE_VERB]: 2, [CK.LINE_VERB]: 2, [CK.QUAD_VERB]: 4, [CK.CONIC_VERB]: 5, [CK.CUBIC_VERB]: 6, [CK.CLOSE_VERB]: 0 };
  for (let i = 0; i < cmds.length;) {
    const verb = cmds[i];
    if (verb === CK.MOVE_VERB) flush();
    part.push(...cmds.slice(i, i + 1 + sizes[verb]));
    i += 1 + sizes[verb];
  }
  flush();
  return contours;
}

/** The area a Skia path fills under its fill type. Winding: the signed areas of its contours
 * add up (PathOps results do not cross themselves). Even-odd: each contour's |area| counts with
 * the sign (-1)^depth, depth the number of other contours around a point just inside it. */
function skiaFilledArea(path) {
  const contours = skiaContours(path);
  const area = (segments) => segments.reduce((sum, s) => sum + (s.weight === undefined ? greenArea(s.points) : 0), 0);
  if (path.getFillType() !== CK.FillType.EvenOdd) return contours.reduce((sum, c) => sum + area(c), 0);
  const polygons = contours.map((c) => c.flatMap((s) => denseSamples(s, 64)));
  let total = 0;
  contours.forEach((c, k) => {
    const a = area(c);
    const poly = polygons[k];
    const p = poly[0], q = poly[1];
    const len = Math.hypot(q[0] - p[0], q[1] - p[1]) || 1;
    const inward = a > 0 ? 1 : -1;  // left of travel for a counter-clockwise contour
    const e = 1e-6;
    const probe = [(p[0] + q[0]) / 2 - (inward * e * (q[1] - p[1])) / len, (p[1] + q[1]) / 2 + (inward * e * (q[0] - p[0])) / len];
    let depth = 0;
    polygons.forEach((other, j) => {
      if (j === k) return;
      let inside = false;
      for (let i = 0, m = other.length - 1; i < other.length; m = i++) {
        const [xi, yi] = other[i], [xm, ym] = other[m];
        if ((yi > probe[1]) !== (ym > probe[1]) && probe[0] < ((xm - xi) * (probe[1] - yi)) / (ym - yi) + xi) inside = !inside;
      }
      depth += inside ? 1 : 0;
    });
    total += Math.abs(a) * (depth % 2 ? -1 : 1);
  });
  return total;
}

// ---- timing ----

function median(values) {
  const v = [...values].sort((a, b) => a - b);
  return v.length % 2 ? v[(v.length - 1) / 2] : (v[v.length / 2 - 1] + v[v.length / 2]) / 2;
}

/** The CPU time (user + system) this process has used, in milliseconds: on a shared machine
 * the figure to set beside Google Benchmark's CPU time (wall time includes the waits for a
 * core). It counts V8's helper threads (garbage collection) too, which are part of the cost. */
function cpuMs() {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
}

/** Runs each job's `run()` (one pass over its inputs, `items` of them) for at least minMs of CPU
 * per round, rounds times, rotating the order each round; returns the median CPU µs per item. */
function timeInterleaved(jobs) {
  const samples = jobs.map(() => []);
  for (let r = 0; r < rounds; ++r) {
    for (let j = 0; j < jobs.length; ++j) {
      const k = (j + r) % jobs.length;
      const job = jobs[k];
      let passes = 0;
      const start = cpuMs();
      let elapsed = 0;
      do {
        job.run();
        ++passes;
        elapsed = cpuMs() - start;
      } while (elapsed < minMs);
      samples[k].push((elapsed * 1000) / (passes * job.items));
    }
  }
  return jobs.map((job, k) => ({ name: job.name, usPerItem: median(samples[k]) }));
}

const fmt = (x, digits = 3) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));

// ---- booleans ----

function booleans() {
  console.log('## booleans: CPU time per pair (median of rounds), largest relative area difference from ours');
  const jobs = [];
  const quality = [];
  for (const n of [...new Set(shapes.pairs.map((p) => p.cubics))]) {
    const pairs = shapes.pairs.filter((p) => p.cubics === n);
    const skia = pairs.map((p) => [skiaOutline(p.a), skiaOutline(p.b)]);
    const pap = pairs.map((p) => [paperOutline(p.a), paperOutline(p.b)]);
    for (const [op, skiaOp, paperOp, key] of [
      ['union', CK.PathOp.Union, 'unite', 'union_area'],
      ['intersection', CK.PathOp.Intersect, 'intersect', 'intersection_area'],
    ]) {
      jobs.push({
        name: `skia ${op} ${n}`, items: pairs.length,
        run: () => { for (const [a, b] of skia) { const r = CK.Path.MakeFromOp(a, b, skiaOp); if (r) r.delete(); } },
      });
      jobs.push({
        name: `paper ${op} ${n}`, items: pairs.length,
        run: () => { for (const [a, b] of pap) a[paperOp](b, { insert: false }); },
      });
      let skiaWorst = 0, paperWorst = 0, skiaFailed = 0;
      pairs.forEach((p, i) => {
        const ours = p[key];
        const r = CK.Path.MakeFromOp(skia[i][0], skia[i][1], skiaOp);
        if (!r) { ++skiaFailed; return; }
        skiaWorst = Math.max(skiaWorst, Math.abs(Math.abs(skiaArea(r)) - ours) / ours);
        r.delete();
        const q = pap[i][0][paperOp](pap[i][1], { insert: false });
        paperWorst = Math.max(paperWorst, Math.abs(Math.abs(q.area) - ours) / ours);
      });
      quality.push({ op, n, skiaWorst, paperWorst, skiaFailed, allOk: pairs.every((p) => p.ok) });
    }
  }
  const times = timeInterleaved(jobs);
  for (const t of times) console.log(`${t.name}: ${fmt(t.usPerItem)} us CPU/pair`);
  for (const q of quality) {
    console.log(`${q.op} ${q.n}: max rel area diff skia ${fmt(q.skiaWorst, 2)} (failed ${q.skiaFailed}), paper ${fmt(q.paperWorst, 2)}; ours ok: ${q.allOk}`);
  }
}

// ---- hard cases ----

function skiaOf(data, evenodd) {
  const p = data ? CK.Path.MakeFromSVGString(data) : CK.Path.MakeFromSVGString('M0 0');
  if (evenodd) p.setFillType(CK.FillType.EvenOdd);
  return p;
}

function paperOf(data, evenodd) {
  const p = new paper.CompoundPath({ pathData: data || '', insert: false });
  p.fillRule = evenodd ? 'evenodd' : 'nonzero';
  return p;
}

const keeps = (op, a, b) => (op === 'union' ? a || b : op === 'intersection' ? a && b : op === 'difference' ? a && !b : a !== b);

function cases() {
  console.log('## hard cases: peer | case | op | ours area | peer area | points wrong / checked | verdict');
  const skiaOps = { union: CK.PathOp.Union, intersection: CK.PathOp.Intersect, difference: CK.PathOp.Difference, xor: CK.PathOp.XOR };
  const paperOps = { union: 'unite', intersection: 'intersect', difference: 'subtract', xor: 'exclude' };
  const notOk = { skia: 0, paper: 0 };
  let lines = 0;
  for (const c of shapes.cases) {
    for (const o of c.ops) {
      ++lines;
      for (const peer of ['skia', 'paper']) {
        let area = NaN, wrong = 0, verdict = '';
        try {
          let contains;
          if (peer === 'skia') {
            const r = CK.Path.MakeFromOp(skiaOf(c.a, c.evenodd), skiaOf(c.b, c.evenodd), skiaOps[o.op]);
            if (!r) throw new Error('MakeFromOp returned null');
            contains = (x, y) => r.contains(x, y);
            area = skiaFilledArea(r);
          } else {
            const r = paperOf(c.a, c.evenodd)[paperOps[o.op]](paperOf(c.b, c.evenodd), { insert: false });
            contains = (x, y) => r.contains(new paper.Point(x, y));
            // The area under the result's fill rule: reorient() turns holes against their
            // parents (it assumes contours that do not cross), then the signed areas add up.
            area = r.clone({ insert: false }).reorient(r.fillRule !== 'evenodd', true).area;
          }
          for (const [x, y, inA, inB] of c.points) {
            if (keeps(o.op, !!inA, !!inB) !== contains(x, y)) ++wrong;
          }
          if (!(Math.abs(Math.abs(area) - o.area) <= c.area_tolerance)) verdict += ' AREA';
          if (wrong > 0) verdict += ' POINTS';
        } catch (e) {
          verdict += ` threw: ${e.message}`;
        }
        if (!o.ok) verdict += ' (ours not ok)';
        if (!verdict) verdict = ' ok';
        else ++notOk[peer];
        console.log(`${peer} | ${c.name} | ${o.op} | ${o.area} | ${area} | ${wrong} / ${c.points.length} |${verdict}`);
      }
    }
  }
  console.log(`lines not ok: skia ${notOk.skia}, paper ${notOk.paper}, of ${lines} each`);
}

// ---- verified error by dense sampling ----

/** Chords in a uniform grid, for the distance from a point to the nearest chord. */
class ChordIndex {
  constructor(cell) {
    this.cell = cell;
    this.cells = new Map();
    this.chords = [];
  }
  key(i, j) { return i * 1000003 + j; }
  add(a, b) {
    const id = this.chords.length;
    this.chords.push([a[0], a[1], b[0], b[1]]);
    const i0 = Math.floor(Math.min(a[0], b[0]) / this.cell), i1 = Math.floor(Math.max(a[0], b[0]) / this.cell);
    const j0 = Math.floor(Math.min(a[1], b[1]) / this.cell), j1 = Math.floor(Math.max(a[1], b[1]) / this.cell);
    for (let i = i0; i <= i1; ++i) {
      for (let j = j0; j <= j1; ++j) {
        const k = this.key(i, j);
        if (!this.cells.has(k)) this.cells.set(k, []);
        this.cells.get(k).push(id);
      }
    }
  }
  addPolyline(points) {
    for (let k = 1; k < points.length; ++k) this.add(points[k - 1], points[k]);
  }
  /** Distance to the nearest chord within `reach` cells' ring; Infinity when none. */
  distance(p, reach = 1) {
    const ci = Math.floor(p[0] / this.cell), cj = Math.floor(p[1] / this.cell);
    let best = Infinity;
    for (let i = ci - reach; i <= ci + reach; ++i) {
      for (let j = cj - reach; j <= cj + reach; ++j) {
        const list = this.cells.get(this.key(i, j));
        if (!list) continue;
        for (const id of list) {
          const [ax, ay, bx, by] = this.chords[id];
          const dx = bx - ax, dy = by - ay, wx = p[0] - ax, wy = p[1] - ay;
          const len2 = dx * dx + dy * dy;
          let t = len2 > 0 ? (wx * dx + wy * dy) / len2 : 0;
          t = Math.min(1, Math.max(0, t));
          const ex = wx - t * dx, ey = wy - t * dy;
          best = Math.min(best, ex * ex + ey * ey);
        }
      }
    }
    return Math.sqrt(best);
  }
}

function denseSamples(segment, count = kDense) {
  const out = [];
  for (let k = 0; k <= count; ++k) out.push(segmentPoint(segment, k / count));
  return out;
}

/** Hausdorff distance (dense sampling, both ways) between curves (segments) and a polyline. */
function flattenError(segments, polyline, cell) {
  const polyIndex = new ChordIndex(cell);
  polyIndex.addPolyline(polyline);
  const curveIndex = new ChordIndex(cell);
  let worst = 0;
  for (const s of segments) {
    const dense = denseSamples(s);
    curveIndex.addPolyline(dense);
    for (const q of dense) worst = Math.max(worst, polyIndex.distance(q));
  }
  for (let k = 1; k < polyline.length; ++k) {
    for (let j = 0; j < 16; ++j) {
      const t = j / 16;
      const a = polyline[k - 1], b = polyline[k];
      worst = Math.max(worst, curveIndex.distance([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]));
    }
  }
  return worst;
}

function flattenSets() {
  return [
    { name: 'glyph outlines (8 x 50 cubics)', shapes: shapes.glyphs.map((g) => ({ segments: outlineCubics(g).map((points) => ({ points })), closed: true, flat: g })) },
    { name: 'random cubics (256)', shapes: shapes.random_cubics.map((c) => ({ segments: [{ points: pointsOf(c) }], closed: false, flat: c })) },
  ];
}

function paperPathOf(shape) {
  if (shape.closed) return paperOutline(shape.flat);
  const p = pointsOf(shape.flat);
  return new paper.Path({
    segments: [new paper.Segment(new paper.Point(p[0][0], p[0][1]), null, new paper.Point(p[1][0] - p[0][0], p[1][1] - p[0][1])),
      new paper.Segment(new paper.Point(p[3][0], p[3][1]), new paper.Point(p[2][0] - p[3][0], p[2][1] - p[3][1]), null)],
    closed: false, insert: false,
  });
}

function flatten() {
  console.log('## flatten: chords at the same verified maximum error (Hausdorff, dense sampling)');
  const sets = flattenSets();
  for (const flatness of [1e-2, 1e-3, 1e-4]) {
    for (const set of sets) {
      let paperChords = 0, paperError = 0;
      for (const shape of set.shapes) {
        const path = paperPathOf(shape);
        path.flatten(flatness);
        const poly = path.segments.map((s) => [s.point.x, s.point.y]);
        if (path.closed) poly.push(poly[0]);
        paperChords += poly.length - 1;
        paperError = Math.max(paperError, flattenError(shape.segments, poly, 4 * flatness));
      }
      const ours = JSON.parse(execFileSync(dumpBinary, ['flatten', String(paperError)], { maxBuffer: 1 << 30 }).toString());
      const ourPolylines = set.name.startsWith('glyph') ? ours.glyphs : ours.random_cubics;
      let ourChords = 0, ourError = 0;
      set.shapes.forEach((shape, i) => {
        const poly = pointsOf(ourPolylines[i]);
        ourChords += poly.length - 1;
        ourError = Math.max(ourError, flattenError(shape.segments, poly, 4 * flatness));
      });
      console.log(`${set.name}, paper flatness ${flatness}: paper ${paperChords} chords, verified error ${fmt(paperError)}; ours at that tolerance ${ourChords} chords, verified error ${fmt(ourError)}; ours / paper ${fmt(ourChords / paperChords)}`);
    }
  }
}

// ---- offset ----

/** The exact offset point B(t) + d N(t) of a cubic (N the left normal, y up). */
function offsetPoint(cubic, t, d) {
  const p = cubic;
  const u = 1 - t;
  const dx = 3 * (u * u * (p[1][0] - p[0][0]) + 2 * u * t * (p[2][0] - p[1][0]) + t * t * (p[3][0] - p[2][0]));
  const dy = 3 * (u * u * (p[1][1] - p[0][1]) + 2 * u * t * (p[2][1] - p[1][1]) + t * t * (p[3][1] - p[2][1]));
  const len = Math.hypot(dx, dy);
  const b = segmentPoint({ points: p }, t);
  return [b[0] - (d * dy) / len, b[1] + (d * dx) / len];
}

/** The error of an offset outline (segments) at distance |d| from the glyph's cubics, both
 * ways; `sides`: the signed distances whose exact offsets the outline must cover. */
function offsetError(cubics, outline, d, sides) {
  const cell = 2 * Math.abs(d);
  const source = new ChordIndex(cell);
  for (const c of cubics) source.addPolyline(denseSamples({ points: c }));
  const out = new ChordIndex(cell);
  let worst = 0;
  for (const s of outline) {
    const dense = denseSamples(s, 64);
    out.addPolyline(dense);
    for (const q of dense) worst = Math.max(worst, Math.abs(source.distance(q) - Math.abs(d)));
  }
  for (const c of cubics) {
    for (const side of sides) {
      for (let k = 0; k <= 256; ++k) worst = Math.max(worst, out.distance(offsetPoint(c, k / 256, side), 2));
    }
  }
  return worst;
}

function paperSegments(path) {
  const out = [];
  const children = path.children ? path.children : [path];
  for (const child of children) {
    for (const c of child.curves) {
      const p1 = c.point1, p2 = c.point2, h1 = c.handle1, h2 = c.handle2;
      out.push({ points: [[p1.x, p1.y], [p1.x + h1.x, p1.y + h1.y], [p2.x + h2.x, p2.y + h2.y], [p2.x, p2.y]] });
    }
  }
  return out;
}

function offset() {
  const d = 0.02;
  console.log(`## offset at d = ${d}: segments at the same verified maximum error`);
  const glyphs = shapes.glyphs;
  // Each peer: a name, the signed distances its outline stands for, and a function from a glyph
  // (control points) to its outline's segments. Adding a stroke peer is one more entry.
  const peers = [];
  // Skia's stroker works to a fixed tolerance in device pixels divided by `precision` (its
  // resScale): on outlines of size 1 it needs precisions in the thousands.
  for (const precision of [1e3, 1e4, 1e5]) {
    peers.push({
      name: `skia stroke (width ${2 * d}, precision ${precision})`, sides: [d, -d],
      run: (g) => {
        const s = skiaOutline(g);
        const r = s.makeStroked({ width: 2 * d, precision, join: CK.StrokeJoin.Round, cap: CK.StrokeCap.Butt });
        const segs = skiaSegments(r);
        r.delete();
        s.delete();
        return segs;
      },
    });
  }
  for (const side of [d, -d]) {
    peers.push({
      name: `paperjs-offset offset(${side})`, sides: [side],
      run: (g) => paperSegments(PaperOffset.offset(paperOutline(g), side, { insert: false, join: 'round' })),
    });
  }
  for (const peer of peers) {
    let segments = 0, error = 0;
    const outs = glyphs.map((g) => peer.run(g));
    // A one-sided peer's sign convention is taken from its output: the side it is nearer.
    if (peer.sides.length === 1) {
      const err = (side) => Math.max(...glyphs.map((g, i) => offsetError(outlineCubics(g), outs[i], d, [side])));
      if (err(-peer.sides[0]) < err(peer.sides[0])) peer.sides = [-peer.sides[0]];
    }
    glyphs.forEach((g, i) => {
      segments += outs[i].length;
      error = Math.max(error, offsetError(outlineCubics(g), outs[i], d, peer.sides));
    });
    let ourSegments = 0, ourError = 0;
    const ours = peer.sides.map((side) => JSON.parse(execFileSync(dumpBinary, ['offset', String(side), String(error)], { maxBuffer: 1 << 30 }).toString()));
    glyphs.forEach((g, i) => {
      const out = [];
      for (const o of ours) for (const c of o.glyphs[i]) out.push({ points: pointsOf(c) });
      ourSegments += out.length;
      ourError = Math.max(ourError, offsetError(outlineCubics(g), out, d, peer.sides));
    });
    console.log(`${peer.name} (our side ${peer.sides.join(', ')}): ${segments} segments, verified error ${fmt(error)}; ours (${peer.sides.length} side(s)) at that tolerance ${ourSegments} cubics, verified error ${fmt(ourError)}; ours / peer ${fmt(ourSegments / segments)}`);
  }
}

// ---- stroke ----
//
// The exact stroke of the inputs below is S = {p : dist(p, path) <= r}, r = width / 2: with
// round joins and caps by definition; with miter joins on the glyph outlines too, since they
// are closed Catmull-Rom splines, tangent-continuous at every joint, where SVG 2's join adds
// nothing to the segments' ribbons (and a point whose nearest path point is a joint is on that
// joint's normal, so in a ribbon). The error of an outline F (closed contours, nonzero rule)
// is the larger of
//  - outward: max over dense samples q of F's segments of dist(q, path) - r (F never reaches
//    farther than r + that; the parts of F inside S count nothing);
//  - inward: over samples p of S's boundary (B(t) ± r N(t) at 257 t per segment and, at open
//    ends, points of the end circles, kept when their distance to the whole path is r within
//    the sampling's error, with n the outward normal there), the smallest δ with p - δ n in F
//    (0 when p is in F): how far F falls short of S there.
// Membership in F is its winding number (of F's closure: see `inside`), computed here from
// dense polylines of its contours (each segment sampled finely enough that its chords are
// within 1e-7 of it).

/** Samples per segment for chords within `tol` of it: n >= sqrt(max|B''| / (8 tol)). */
function samplesFor(s, tol = 1e-7) {
  const p = s.points, n = p.length - 1;
  if (n === 1) return 1;
  let second = 0;
  for (let i = 0; i + 2 <= n; ++i) {
    second = Math.max(second, Math.hypot(p[i + 2][0] - 2 * p[i + 1][0] + p[i][0], p[i + 2][1] - 2 * p[i + 1][1] + p[i][1]));
  }
  // A conic of weight w <= 1 bends at most like its quadratic over w (Skia's round joins).
  const bound = n * (n - 1) * second / (s.weight !== undefined ? Math.min(1, s.weight) : 1);
  return Math.min(8192, Math.max(4, Math.ceil(Math.sqrt(bound / (8 * tol)))));
}

/** Winding numbers of closed polylines about points: edges kept in horizontal bands. */
class WindingIndex {
  constructor(band) {
    this.band = band;
    this.bands = new Map();
  }
  addEdge(a, b) {
    if (a[1] === b[1]) return;
    const j0 = Math.floor(Math.min(a[1], b[1]) / this.band), j1 = Math.floor(Math.max(a[1], b[1]) / this.band);
    for (let j = j0; j <= j1; ++j) {
      if (!this.bands.has(j)) this.bands.set(j, []);
      this.bands.get(j).push(a[0], a[1], b[0], b[1]);
    }
  }
  /** Winding number about p (counter-clockwise positive, y up): crossings of the ray to +x. */
  at(p) {
    const list = this.bands.get(Math.floor(p[1] / this.band));
    if (!list) return 0;
    let w = 0;
    for (let i = 0; i < list.length; i += 4) {
      const ay = list[i + 1], by = list[i + 3];
      if ((ay <= p[1]) === (by <= p[1])) continue;
      const ax = list[i], bx = list[i + 2];
      const x = ax + ((p[1] - ay) * (bx - ax)) / (by - ay);
      if (x > p[0]) w += by > ay ? 1 : -1;
    }
    return w;
  }
}

/** Outward and inward error of an outline (contours of segments) against S = {dist <= r} of a
 * path of cubics (`closed`: no end circles). */
function strokeError(cubics, closed, contours, r) {
  const source = new ChordIndex(r);
  for (const c of cubics) source.addPolyline(denseSamples({ points: c }));
  const winding = new WindingIndex(r / 8);
  let outward = 0;
  for (const contour of contours) {
    const poly = [];
    for (const s of contour) {
      const dense = denseSamples(s, samplesFor(s));
      if (poly.length) dense.shift();
      poly.push(...dense);
    }
    for (const q of poly) {
      let d = source.distance(q, 2);
      for (let reach = 8; !Number.isFinite(d) && reach <= 4096; reach *= 8) d = source.distance(q, reach);
      outward = Math.max(outward, d - r);
    }
    for (let k = 1; k < poly.length; ++k) winding.addEdge(poly[k - 1], poly[k]);
    winding.addEdge(poly[poly.length - 1], poly[0]);
  }
  const boundary = [];
  for (const c of cubics) {
    for (let k = 0; k <= 256; ++k) {
      const t = k / 256;
      const b = segmentPoint({ points: c }, t);
      for (const side of [r, -r]) {
        const p = offsetPoint(c, t, side);
        const len = Math.hypot(p[0] - b[0], p[1] - b[1]);
        if (len > 0) boundary.push([p, [(p[0] - b[0]) / len, (p[1] - b[1]) / len]]);
      }
    }
  }
  if (!closed) {
    for (const e of [cubics[0][0], cubics[cubics.length - 1][3]]) {
      for (let k = 0; k < 256; ++k) {
        const a = (2 * Math.PI * k) / 256, n = [Math.cos(a), Math.sin(a)];
        boundary.push([[e[0] + r * n[0], e[1] + r * n[1]], n]);
      }
    }
  }
  let inward = 0, checked = 0;
  for (const [p, n] of boundary) {
    // A point of S's boundary: nothing of the path nearer than r (within the dense chords'
    // sagitta and rounding).
    if (source.distance(p, 2) < r - 1e-6) continue;
    ++checked;
    // Membership in F's closure: a point on an edge two contours share (the normal line where
    // two pieces of an outline meet) reads winding 0 by the ray's convention, so the point or
    // one of its neighbours 1e-9 away along the boundary's tangent counts.
    const inside = (d) => [0, 1e-9, -1e-9].some((e) => winding.at([p[0] - d * n[0] - e * n[1], p[1] - d * n[1] + e * n[0]]) !== 0);
    if (inside(0)) continue;
    let lo = 0, hi = 1e-9;
    while (hi < r && !inside(hi)) { lo = hi; hi *= 2; }
    if (hi >= r) { inward = Math.max(inward, r); continue; }
    for (let k = 0; k < 40; ++k) {
      const mid = (lo + hi) / 2;
      if (inside(mid)) hi = mid; else lo = mid;
    }
    inward = Math.max(inward, hi);
  }
  return { outward, inward, error: Math.max(outward, inward), checked };
}

function ourStroke(width, tolerance, join, cap) {
  const out = JSON.parse(execFileSync(dumpBinary, ['stroke', String(width), String(tolerance), join, cap], { maxBuffer: 1 << 30 }).toString());
  const shape = (contours) => contours.map((c) => c.map((flat) => ({ points: pointsOf(flat) })));
  return { glyphs: out.glyphs.map(shape), random_cubics: out.random_cubics.map(shape) };
}

function stroke() {
  const width = 0.04, r = width / 2;
  console.log(`## stroke at width ${width}: segments at the same verified maximum error; CPU time per stroked shape`);
  const sets = [
    { key: 'glyphs', name: 'glyph outlines (8 x 50 cubics, closed)', closed: true, inputs: shapes.glyphs, skia: skiaOutline, paper: paperOutline },
  ];
  const styles = [
    { join: 'round', cap: 'round', skiaJoin: CK.StrokeJoin.Round, skiaCap: CK.StrokeCap.Round },
    { join: 'miter', cap: 'butt', skiaJoin: CK.StrokeJoin.Miter, skiaCap: CK.StrokeCap.Butt },
  ];
  const t0 = Date.now();
  const timing = [];
  for (const set of sets) {
    for (const style of styles) {
      // Butt caps on open cubics: S is not {dist <= r} there; only the closed outlines (no caps)
      // are measured with miter joins.
      if (!set.closed && style.cap !== 'round') continue;
      const peers = [];
      for (const precision of [1e3, 1e4, 1e5]) {
        const stroked = (path) => path.makeStroked({ width, precision, join: style.skiaJoin, cap: style.skiaCap, miter_limit: 4 });
        peers.push({
          name: `skia makeStroked (precision ${precision})`, precision, stroked,
          run: (f) => {
            const s = set.skia(f);
            const o = stroked(s);
            const segs = skiaContours(o);
            o.delete();
            s.delete();
            return segs;
          },
        });
      }
      peers.push({
        name: 'paperjs-offset offsetStroke',
        run: (f) => {
          const o = PaperOffset.offsetStroke(set.paper(f), r, { insert: false, join: style.join, cap: style.cap, limit: 4 });
          const children = o.children ? o.children : [o];
          return children.map((c) => paperSegments(c));
        },
      });
      for (const peer of peers) {
        let segments = 0, error = 0, outward = 0, inward = 0;
        set.inputs.forEach((f) => {
          const contours = peer.run(f);
          for (const c of contours) segments += c.length;
          const e = strokeError(set.closed ? outlineCubics(f) : [pointsOf(f)], set.closed, contours, r);
          error = Math.max(error, e.error);
          outward = Math.max(outward, e.outward);
          inward = Math.max(inward, e.inward);
        });
        if (!(error > 0 && error < r)) {
          console.log(`${set.name}, ${style.join} join, ${style.cap} cap, ${peer.name} [${((Date.now() - t0) / 1000).toFixed(0)} s]: ${segments} segments, verified error ${fmt(error)} (out ${fmt(outward)}, in ${fmt(inward)}): not compared`);
          continue;
        }
        const ours = ourStroke(width, error, style.join, style.cap)[set.key];
        let ourSegments = 0, ourError = 0, ourOutward = 0, ourInward = 0;
        set.inputs.forEach((f, i) => {
          for (const c of ours[i]) ourSegments += c.length;
          const e = strokeError(set.closed ? outlineCubics(f) : [pointsOf(f)], set.closed, ours[i], r);
          ourError = Math.max(ourError, e.error);
          ourOutward = Math.max(ourOutward, e.outward);
          ourInward = Math.max(ourInward, e.inward);
        });
        console.log(`${set.name}, ${style.join} join, ${style.cap} cap, ${peer.name} [${((Date.now() - t0) / 1000).toFixed(0)} s]: ${segments} segments, verified error ${fmt(error)} (out ${fmt(outward)}, in ${fmt(inward)}); ours at that tolerance ${ourSegments} segments, verified error ${fmt(ourError)} (out ${fmt(ourOutward)}, in ${fmt(ourInward)}); ours / peer ${fmt(ourSegments / segments)}`);
        if (peer.precision) {
          const skiaPaths = set.inputs.map((f) => set.skia(f));
          timing.push({
            label: `${set.name}, ${style.join}/${style.cap}, precision ${peer.precision} (tolerance ${fmt(error)})`,
            skia: { name: 'skia', items: skiaPaths.length, run: () => { for (const s of skiaPaths) peer.stroked(s).delete(); } },
            ours: ['stroke-time', set.key, String(width), String(error), style.join, style.cap, String(minMs)],
          });
        }
      }
    }
  }
  // Timing: each round runs Skia's stroker (this process's CPU time) and ours (the child's own
  // CPU time) for at least minMs each, in an order alternating round by round.
  console.log('### CPU time per stroked shape (median of rounds): skia | ours | ours / skia (each round\'s ratio)');
  for (const t of timing) {
    const skiaUs = [], ourUs = [], ratios = [];
    for (let round = 0; round < rounds; ++round) {
      const runSkia = () => {
        let passes = 0;
        const start = cpuMs();
        let elapsed = 0;
        do { t.skia.run(); ++passes; elapsed = cpuMs() - start; } while (elapsed < minMs);
        return (elapsed * 1000) / (passes * t.skia.items);
      };
      const runOurs = () => JSON.parse(execFileSync(dumpBinary, t.ours).toString()).us_per_shape;
      let a, b;
      if (round % 2 === 0) { a = runSkia(); b = runOurs(); } else { b = runOurs(); a = runSkia(); }
      skiaUs.push(a);
      ourUs.push(b);
      ratios.push(b / a);
    }
    console.log(`${t.label}: skia ${fmt(median(skiaUs))} us | ours ${fmt(median(ourUs))} us | ${fmt(median(ratios))} (${ratios.map((x) => fmt(x, 2)).join(', ')})`);
  }
}

for (const s of sections) {
  if (s === 'stroke') stroke();
  else if (s === 'booleans') booleans();
  else if (s === 'cases') cases();
  else if (s === 'flatten') flatten();
  else if (s === 'offset') offset();
  else throw new Error(`unknown section ${s}`);
}
