// The mapping between the drawing's world coordinates and the canvas. The world is a
// fixed 800 x 600 box with y pointing up (so signed areas have their usual sign); the
// canvas shows all of it at any width, keeping the aspect ratio, sharp on high-DPI
// screens. Control points are snapped to whole world units.

export const kWorld = Object.freeze({width: 800, height: 600});

export class View {
  constructor(canvas) {
    this.canvas = canvas;
    this.cssWidth = kWorld.width;
    this.cssHeight = kWorld.height;
    this.ratio = 1;
  }

  /** Sizes the canvas to `cssWidth` CSS pixels; returns whether anything changed. */
  resize(cssWidth, devicePixelRatio) {
    const width = Math.max(160, Math.floor(cssWidth));
    const height = Math.round(width * kWorld.height / kWorld.width);
    const ratio = Math.max(1, devicePixelRatio || 1);
    if (width === this.cssWidth && height === this.cssHeight && ratio === this.ratio &&
        this.canvas.width === Math.round(width * ratio)) {
      return false;
    }
    this.cssWidth = width;
    this.cssHeight = height;
    this.ratio = ratio;
    this.canvas.style.width = `${width}px`;
    this.canvas.style.height = `${height}px`;
    this.canvas.width = Math.round(width * ratio);
    this.canvas.height = Math.round(height * ratio);
    return true;
  }

  /** CSS pixels per world unit. */
  get scale() {
    return this.cssWidth / kWorld.width;
  }

  /** World point [x, y] to canvas CSS pixels [sx, sy] (origin top left). */
  toScreen(p) {
    return [p[0] * this.scale, (kWorld.height - p[1]) * this.scale];
  }

  /** Canvas CSS pixels to the world point, unrounded. */
  toWorld(sx, sy) {
    return [sx / this.scale, kWorld.height - sy / this.scale];
  }

  /** Canvas CSS pixels to the nearest whole-unit world point inside the box. */
  snappedWorld(sx, sy) {
    const [x, y] = this.toWorld(sx, sy);
    const clamp = (v, hi) => Math.min(hi, Math.max(0, Math.round(v)));
    return [clamp(x, kWorld.width), clamp(y, kWorld.height)];
  }

  /** A 2-D context drawing in CSS pixels, cleared to transparent (no background: the
   *  grid behind it is CSS, so a PNG export carries only the drawing). */
  context() {
    const ctx = this.canvas.getContext('2d');
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    ctx.setTransform(this.ratio, 0, 0, this.ratio, 0, 0);
    return ctx;
  }
}
