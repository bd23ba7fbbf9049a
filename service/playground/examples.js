// The examples in the "Examples" menu: control points in world units (800 x 600, y up).
// `b`, when present, is the second curve. The overlap example's B is A's piece on
// [0.25, 0.75] (control points from the blossom: B(0.25), b(0.25, 0.75), B(0.75)), so
// the two coincide there exactly.

export const kExamples = Object.freeze({
  loop: {a: [[250, 100], [750, 560], [50, 560], [550, 100]]},
  crossing: {a: [[80, 120], [260, 560], [520, 40], [720, 480]], b: [[100, 480], [300, 60], [560, 580], [740, 160]]},
  tangent: {a: [[100, 100], [300, 500], [500, 100]], b: [[150, 300], [450, 300]]},
  overlap: {a: [[100, 100], [300, 500], [500, 100]], b: [[200, 250], [300, 350], [400, 250]]},
  closed: {a: [[200, 150], [60, 520], [740, 520], [600, 150], [200, 150]]},
  inflections: {a: [[420, 120], [420, 480], [780, 480], [60, 300]]},
});
