// Text labels on the canvas, placed so that none overlaps another. Labels are
// collected while the scene is drawn and placed at the end, most important first
// (control points, then B(t0), then the construction's points, then areas and
// distances): each tries eight positions around its anchor and takes the first that
// stays inside the canvas and clear of the labels already placed; a label with no free
// position is left out (its point is still drawn, and the panels list every value).

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
  }

  /** A label for the screen point (sx, sy); lower `rank` is placed first. */
  add(sx, sy, text, color, rank) {
    this.pending.push({sx, sy, text, color, rank, order: this.pending.length});
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
      const {sx, sy} = label;
      const candidates = [
        [sx + kGap, sy - kGap - h], [sx + kGap, sy + kGap], [sx - kGap - w, sy - kGap - h], [sx - kGap - w, sy + kGap],
        [sx + kGap + 2, sy - h / 2], [sx - kGap - 2 - w, sy - h / 2], [sx - w / 2, sy - kGap - h - 2], [sx - w / 2, sy + kGap + 2],
      ];
      const box = candidates.map(([x, y]) => ({text: label.text, x, y, w, h}))
          .find((b) => b.x >= 0 && b.y >= 0 && b.x + b.w <= this.width && b.y + b.h <= this.height &&
                       !this.placed.some((p) => overlaps(b, p)));
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
}
