// The state in the URL fragment, so a link reproduces the drawing:
//   #a=100,120;240,480;560,500&b=…&t0=0.37&edit=b
// a and b the curves' control points (x,y pairs in the drawing's units, y up, numbers
// in the shortest form that reads back to the same double), b present when the second
// curve is shown, t0 the polar parameter, edit the curve being edited. A curve in path
// mode is its SVG path data as pasted, percent-encoded, in pa (or pb), its points empty.

const encodePoints = (points) => points.map((p) => p.map(String).join(',')).join(';');

/** The fragment (without '#') for a state. */
export function encodeFragment(state) {
  const parts = [`a=${encodePoints(state.curves[0].points)}`];
  if (state.curves[0].path) parts.push(`pa=${encodeURIComponent(state.curves[0].path)}`);
  if (state.second) {
    parts.push(`b=${encodePoints(state.curves[1].points)}`);
    if (state.curves[1].path) parts.push(`pb=${encodeURIComponent(state.curves[1].path)}`);
  }
  parts.push(`t0=${state.t0}`);
  if (state.active === 1) parts.push('edit=b');
  return parts.join('&');
}

function decodePoints(text, name) {
  if (text === '') return [];
  return text.split(';').map((pair, k) => {
    const p = pair.split(',').map(Number);
    if (p.length !== 2 || !p.every(Number.isFinite)) throw new Error(`point ${k} of ${name} is not two numbers: "${pair}"`);
    return p;
  });
}

/** {curves: [a, b], paths: [pa, pb] (null where absent), second, t0, active} from a fragment, null when empty; throws Error when malformed. */
export function decodeFragment(fragment) {
  const text = fragment.replace(/^#/, '');
  if (!text) return null;
  const fields = new Map(text.split('&').map((part) => {
    const at = part.indexOf('=');
    return at < 0 ? [part, ''] : [part.slice(0, at), decodeURIComponent(part.slice(at + 1))];
  }));
  if (!fields.has('a')) throw new Error('the link has no curve (a=…)');
  const t0 = fields.has('t0') ? Number(fields.get('t0')) : 0.5;
  if (!(t0 >= 0 && t0 <= 1)) throw new Error(`t0 must be in [0, 1], got "${fields.get('t0')}"`);
  const second = fields.has('b');
  const paths = [fields.get('pa') || null, second ? fields.get('pb') || null : null];
  return {
    curves: [paths[0] ? [] : decodePoints(fields.get('a'), 'a'), second && !paths[1] ? decodePoints(fields.get('b'), 'b') : []],
    paths,
    second,
    t0,
    active: second && fields.get('edit') === 'b' ? 1 : 0,
  };
}
