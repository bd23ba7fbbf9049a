// The state in the URL fragment, so a link reproduces the drawing:
//   #a=100,120;240,480;560,500&b=…&t0=0.37&edit=b&hide=polar,box
// a and b the curves' control points (x,y pairs in the drawing's units, y up, numbers
// in the shortest form that reads back to the same double), b present when the second
// curve is shown, t0 the polar parameter, edit the curve being edited, hide the layers
// switched off (the names of state.show). A curve in path mode is its SVG path data as
// pasted, percent-encoded, in pa (or pb), its points empty. The other views add:
//   view=regions&ra=…&rb=…&op=union&fa=nonzero&fb=evenodd  (the two shapes' path data,
//     the operation, each shape's fill rule)
//   view=outline&op=…&tol=0.5&d=-20[&sw=40&join=round&cap=round]  (the path data,
//     the flattening and offset tolerance, the signed offset distance; the stroke's
//     width, join and cap when the path is stroked)

export const kLayers = Object.freeze(['polygon', 'curve', 'points', 'labels', 'polar', 'polarPoints', 'casteljau', 'frame',
                                      'box', 'nearest', 'loops', 'classify', 'intersections']);
export const kOperations = Object.freeze(['union', 'intersection', 'difference', 'xor', 'simplify']);
export const kFillRules = Object.freeze(['nonzero', 'evenodd']);

const encodePoints = (points) => points.map((p) => p.map(String).join(',')).join(';');
const text = (value) => encodeURIComponent(value);

/** The fragment (without '#') for a state. */
export function encodeFragment(state) {
  const parts = [`a=${encodePoints(state.curves[0].points)}`];
  if (state.curves[0].path) parts.push(`pa=${text(state.curves[0].path)}`);
  if (state.second) {
    parts.push(`b=${encodePoints(state.curves[1].points)}`);
    if (state.curves[1].path) parts.push(`pb=${text(state.curves[1].path)}`);
  }
  parts.push(`t0=${state.t0}`);
  if (state.active === 1) parts.push('edit=b');
  const hidden = kLayers.filter((layer) => !state.show[layer]);
  if (hidden.length) parts.push(`hide=${hidden.join(',')}`);
  if (state.view === 'regions') {
    const r = state.regions;
    parts.push('view=regions', `ra=${text(r.a)}`, `rb=${text(r.b)}`, `op=${r.op}`, `fa=${r.fillA}`, `fb=${r.fillB}`);
  } else if (state.view === 'outline') {
    const o = state.outline;
    parts.push('view=outline', `op=${text(o.path)}`, `tol=${o.tolerance}`, `d=${o.distance}`);
    if (o.stroke) parts.push(`sw=${o.stroke.width}`, `join=${o.stroke.join}`, `cap=${o.stroke.cap}`);
  }
  return parts.join('&');
}

function decodePoints(value, name) {
  if (value === '') return [];
  return value.split(';').map((pair, k) => {
    const p = pair.split(',').map(Number);
    if (p.length !== 2 || !p.every(Number.isFinite)) throw new Error(`point ${k} of ${name} is not two numbers: "${pair}"`);
    return p;
  });
}

function oneOf(fields, key, allowed, fallback) {
  if (!fields.has(key)) return fallback;
  const value = fields.get(key);
  if (!allowed.includes(value)) throw new Error(`${key} must be one of ${allowed.join(', ')}, got "${value}"`);
  return value;
}

function number(fields, key, fallback, ok, what) {
  if (!fields.has(key)) return fallback;
  const value = Number(fields.get(key));
  if (!(Number.isFinite(value) && ok(value))) throw new Error(`${key} must be ${what}, got "${fields.get(key)}"`);
  return value;
}

/**
 * {curves: [a, b], paths: [pa, pb] (null where absent), second, t0, active, hidden (layer
 * names), view, regions ({a, b, op, fillA, fillB} or null), outline ({path, tolerance,
 * distance, stroke ({width, join, cap} or null)} or null)} from a fragment, null when empty; throws Error when malformed.
 */
export function decodeFragment(fragment) {
  const body = fragment.replace(/^#/, '');
  if (!body) return null;
  const fields = new Map(body.split('&').map((part) => {
    const at = part.indexOf('=');
    return at < 0 ? [part, ''] : [part.slice(0, at), decodeURIComponent(part.slice(at + 1))];
  }));
  const view = oneOf(fields, 'view', ['curves', 'regions', 'outline'], 'curves');
  if (!fields.has('a') && view === 'curves') throw new Error('the link has no curve (a=…)');
  const t0 = number(fields, 't0', 0.5, (v) => v >= 0 && v <= 1, 'in [0, 1]');
  const second = fields.has('b');
  const paths = [fields.get('pa') || null, second ? fields.get('pb') || null : null];
  const hidden = fields.get('hide') ? fields.get('hide').split(',') : [];
  const unknown = hidden.find((layer) => !kLayers.includes(layer));
  if (unknown !== undefined) throw new Error(`hide names an unknown layer "${unknown}"`);
  let regions = null;
  let outline = null;
  if (view === 'regions') {
    if (!fields.get('ra')) throw new Error('a regions link needs its first shape (ra=…)');
    regions = {a: fields.get('ra'), b: fields.get('rb') ?? '', op: oneOf(fields, 'op', kOperations, 'union'),
               fillA: oneOf(fields, 'fa', kFillRules, 'nonzero'), fillB: oneOf(fields, 'fb', kFillRules, 'nonzero')};
  } else if (view === 'outline') {
    if (!fields.get('op')) throw new Error('an outline link needs its path (op=…)');
    outline = {path: fields.get('op'), tolerance: number(fields, 'tol', 0.5, (v) => v > 0, 'positive', 0.5),
               distance: number(fields, 'd', -20, () => true, 'a number'),
               stroke: fields.has('sw') ? {width: number(fields, 'sw', 40, (v) => v > 0, 'positive'),
                                           join: oneOf(fields, 'join', ['miter', 'round', 'bevel'], 'miter'),
                                           cap: oneOf(fields, 'cap', ['butt', 'round', 'square'], 'butt')} : null};
  }
  return {
    curves: [paths[0] || !fields.has('a') ? [] : decodePoints(fields.get('a'), 'a'),
             second && !paths[1] ? decodePoints(fields.get('b'), 'b') : []],
    paths,
    second,
    t0,
    active: second && fields.get('edit') === 'b' ? 1 : 0,
    hidden,
    view,
    regions,
    outline,
  };
}
