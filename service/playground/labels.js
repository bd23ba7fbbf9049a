// Text labels on the canvas, placed so that none overlaps another, nor covers a mark
// (a control point, B(t0), a construction point: their discs are kept clear), and so
// that a label marking a region (an area) does not lie across a circle drawn on the
// canvas (the osculating circle). Labels are collected
// while the scene is drawn and placed at the end, most important first (control
// points, then B(t0), then the construction's points, then areas and distances): each
// tries eight positions around its anchor, then eight three times as far (then around
// its other anchors, for a label that may stand in several places), and takes the first
// that stays inside the canvas and clear of everything placed or kept clear; a label
// with no free position is left out (its point is still drawn, and the panels list
// every value).

const kFont = '12px system-ui, sans-serif';
const kHeight = 14;  // CSS pixels of one line of kFont, with a little air
const kGap = 6;  // between the anchor and the text

/** Unicode subscript and superscript digits, for names such as b₁² (b_1^2). */
const kSub = '₀₁₂₃₄₅₆₇₈₉';
const kSup = '⁰¹²³⁴⁵⁶⁷⁸⁹';
export const subscript = (n) => String(n).replace(/\d/g, (d) => kSub[d]);
export const superscript = (n) => String(n).replace(/\d/g, (d) => kSup[d]);

function overlaps(a, b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

export class LabelLayout {
  /** width, height: the canvas in CSS pixels. */
  constructor(width, height) {
    this.width = width;
    this.height = height;
    this.pending = [];
    this.placed = [];  // [{text, x, y, w, h}]: boxes in CSS pixels (x, y the top left)
    this.dropped = [];  // texts that found no free place
    this.marks = [];  // [{x, y, w, h}]: the discs of marks, as boxes, kept clear
    this.rings = [];  // [{cx, cy, r}]: circles whose line no label may cross
  }

  /** A mark's disc of `radius` CSS pixels at (sx, sy), which no label may cover. */
  keepClear(sx, sy, radius) {
    this.marks.push({x: sx - radius, y: sy - radius, w: 2 * radius, h: 2 * radius});
  }

  /** A circle (centre and radius in CSS pixels) whose line no label may cross. */
  keepOffRing(cx, cy, r) {
    this.rings.push({cx, cy, r});
  }

  /** Whether box b lies across one of the rings: some of it inside the circle, some outside. */
  crossesRing(b) {
    return this.rings.some(({cx, cy, r}) => {
      const nx = Math.min(Math.max(cx, b.x), b.x + b.w) - cx;
      const ny = Math.min(Math.max(cy, b.y), b.y + b.h) - cy;
      const fx = Math.max(Math.abs(b.x - cx), Math.abs(b.x + b.w - cx));
      const fy = Math.max(Math.abs(b.y - cy), Math.abs(b.y + b.h - cy));
      return Math.hypot(nx, ny) <= r + 2 && Math.hypot(fx, fy) >= r - 2;
    });
  }

  /** A label for the screen point (sx, sy); lower `rank` is placed first; offRings: it keeps off the rings. */
  add(sx, sy, text, color, rank, offRings = false) {
    this.pending.push({anchors: [[sx, sy]], text, color, rank, offRings, order: this.pending.length});
  }

  /** A label that may stand at any of `anchors` ([[sx, sy], ...], the first preferred), such as
   * a region's name at its centre or, when that is taken, beside points along its boundary. */
  addAnywhere(anchors, text, color, rank, offRings = false) {
    this.pending.push({anchors, text, color, rank, offRings, order: this.pending.length});
  }

  /** A label left out on purpose (listed with those that found no place). */
  omit(text) {
    this.dropped.push(text);
  }

  /** Boxes to keep clear, such as the tooltip or the legend. */
  reserve(x, y, w, h) {
    this.placed.push({text: '', x, y, w, h});
  }

  /** Places and draws every label. */
  draw(ctx) {
    ctx.save();
    ctx.font = kFont;
    ctx.textAlign = 'left';
    ctx.textBaseline = 'middle';
    this.pending.sort((a, b) => a.rank - b.rank || a.order - b.order);
    for (const label of this.pending) {
      const w = ctx.measureText(label.text).width + 2;
      const h = kHeight;
      const candidates = label.anchors.flatMap(([sx, sy]) => [kGap, 3 * kGap].flatMap((gap) => [
        [sx + gap, sy - gap - h], [sx + gap, sy + gap], [sx - gap - w, sy - gap - h], [sx - gap - w, sy + gap],
        [sx + gap + 2, sy - h / 2], [sx - gap - 2 - w, sy - h / 2], [sx - w / 2, sy - gap - h - 2], [sx - w / 2, sy + gap + 2],
      ]));
      const box = candidates.map(([x, y]) => ({text: label.text, x, y, w, h}))
          .find((b) => b.x >= 0 && b.y >= 0 && b.x + b.w <= this.width && b.y + b.h <= this.height &&
                       !this.placed.some((p) => overlaps(b, p)) && !this.marks.some((m) => overlaps(b, m)) &&
                       !(label.offRings && this.crossesRing(b)));
      if (!box) {
        this.dropped.push(label.text);
        continue;
      }
      this.placed.push(box);
      ctx.lineWidth = 3;
      ctx.strokeStyle = 'rgba(255,255,255,0.9)';
      ctx.strokeText(label.text, box.x + 1, box.y + h / 2);
      ctx.fillStyle = label.color;
      ctx.fillText(label.text, box.x + 1, box.y + h / 2);
    }
    ctx.restore();
  }

  /** The placed labels' boxes (reserved boxes left out). */
  boxes() {
    return this.placed.filter((b) => b.text !== '').map((b) => ({...b}));
  }

  /** The marks' discs kept clear, as boxes, and the rings. */
  obstacles() {
    return {marks: this.marks.map((m) => ({...m})), rings: this.rings.map((r) => ({...r}))};
  }
}
