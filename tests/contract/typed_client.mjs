// Writes, to stdout, a TypeScript client that sends every curl example of README.md
// through the types openapi-typescript generates from api/openapi.yaml (imported from
// "./api"), for `tsc --strict` to check (tests/contract/typed_client.sh):
//   - each request body is typed as its operation's JSON request body, and each answer
//     as the response of its status (200, or the problem's `status`);
//   - each body and answer again with one member added, and each body with one control
//     point given a third coordinate among 2-D points, under `@ts-expect-error`: the
//     generated types must refuse them (closed objects, tuples), or the unused directive
//     fails.
// An answer that is a problem answers a request the service refused, so that request is
// sent untyped; its answer is typed all the same.
// Then the mistakes the types must catch (kMistakes, each under `@ts-expect-error`: a body
// with neither or both of `points` and `path`, `t: null`, no curves, a /classify of other
// than four points, a /batch item naming no route or carrying another route's body...),
// the near misses they must accept (kAccepted: a member of the other shape set to null),
// and functions that tell answers apart by the members that distinguish them (a path's
// `segment_count`, the interval's `interval`, a path search's `candidate_pairs`), which
// compile only while those members discriminate the unions.
//
// The examples are found as tests/integration/readme_examples_test.cpp finds them: a line
// starting `curl -s localhost:8080`, with `\` continuation lines, `-d '<body>'`, then
// the answer in the ```json block right after the command's block.
//
// usage: node typed_client.mjs README.md > client.ts
import { readFileSync } from "node:fs";

const kUnknownMember = "unexpected_member";

function readmeExamples(text) {
  const lines = text.split("\n");
  const examples = [];
  for (let i = 0; i < lines.length; ++i) {
    if (!lines[i].startsWith("curl -s localhost:8080")) continue;
    const line = i + 1;
    let command = lines[i];
    while (command.endsWith("\\") && i + 1 < lines.length) command = command.slice(0, -1) + lines[++i];
    const host = "localhost:8080";
    const pathAt = command.indexOf(host) + host.length;
    const bodyAt = command.indexOf("-d '");
    if (bodyAt < 0) continue;  // a GET: no body to type
    const path = command.slice(pathAt, command.indexOf(" ", pathAt));
    const body = command.slice(bodyAt + 4, command.indexOf("'", bodyAt + 4));
    if (lines[i + 1] !== "```" || lines[i + 2] !== "```json") {
      throw new Error(`README.md:${line}: no \`\`\`json answer after the example`);
    }
    let answer = "";
    for (let k = i + 3; k < lines.length && lines[k] !== "```"; ++k) answer += lines[k] + "\n";
    examples.push({ line, path, body: JSON.parse(body), answer: JSON.parse(answer) });
  }
  return examples;
}

function isProblem(answer) {
  return typeof answer === "object" && answer !== null && typeof answer.type === "string" &&
         answer.type.startsWith("urn:bezier-service:problem:") && Number.isInteger(answer.status);
}

function withUnknownMember(value) {
  return { ...value, [kUnknownMember]: 1 };
}

const isPoint2 = (v) => Array.isArray(v) && v.length === 2 && v.every((c) => typeof c === "number");

// The body with the first of its control points (`points`, or the first curve's) given a
// third coordinate among 2-D points, or null when it has no such list. Only these lists:
// elsewhere a body may hold JSON the spec leaves free (a /batch item's body).
function withRaggedPoint(body) {
  const ragged = (points) => [[...points[0], 0], ...points.slice(1)];
  const planar = (points) => Array.isArray(points) && points.length >= 2 && points.every(isPoint2);
  if (planar(body.points)) return { ...body, points: ragged(body.points) };
  if (Array.isArray(body.curves) && planar(body.curves[0]?.points)) {
    return { ...body, curves: [{ ...body.curves[0], points: ragged(body.curves[0].points) }, ...body.curves.slice(1)] };
  }
  return null;
}

const literal = (value) => JSON.stringify(value);  // one line: @ts-expect-error covers one

const cubic = [[0, 0], [1, 2], [3, 2], [4, 0]];
const segment = [[0, 0], [3, 4]];

// [route, why, body]: bodies the generated types must refuse.
const kMistakes = [
  ["/length", "neither points nor path", {}],
  ["/length", "both points and path", { points: segment, path: "M0 0 L3 4" }],
  ["/length", "an interval with a path", { path: "M0 0 L3 4", interval: [0, 0.5] }],
  ["/length", "arc_tolerance with points", { points: segment, arc_tolerance: 0.001 }],
  ["/bounds", "neither points nor path", { interval: [0, 1] }],
  ["/loop-area", "both points and path", { points: cubic, path: "M0 0 C1 2 3 2 4 0" }],
  ["/nearest", "3-D targets with a path", { path: "M0 0 L3 4", targets: [[1, 1, 1]] }],
  ["/flatten", "both points and path", { points: segment, path: "M0 0 L3 4", tolerance: 0.1 }],
  ["/offset", "neither points nor path", { distance: 1, tolerance: 0.1 }],
  ["/offset", "arc_tolerance with points", { points: segment, distance: 1, tolerance: 0.1, arc_tolerance: 0.001 }],
  ["/evaluate", "t null and no samples", { points: segment, t: null }],
  ["/evaluate", "neither t nor samples", { points: segment }],
  ["/evaluate", "both t and samples", { points: segment, t: 0.5, samples: 3 }],
  ["/evaluate", "samples null and no t", { points: segment, samples: null }],
  ["/polar", "both t and samples", { points: cubic, t0: 0.5, t: 0.5, samples: 3 }],
  ["/intersections", "no curves", { curves: [] }],
  ["/intersections", "three curves", { curves: [{ points: segment }, { points: segment }, { points: segment }] }],
  ["/intersections", "a curve with both points and path", { curves: [{ points: segment, path: "M0 0 L3 4" }] }],
  ["/classify", "three points", { points: [[0, 0], [1, 2], [2, 0]] }],
  ["/classify", "five points", { points: [...cubic, [5, 1]] }],
  ["/contains", "a region with both path and curves", { path: "M0 0 H1 V1 Z", curves: [], targets: [[0, 0]] }],
  ["/boolean", "an operand with both path and curves", { op: "simplify", a: { path: "M0 0 H1 V1 Z", curves: [] } }],
  ["/batch", "an item naming no route", { requests: [{ path: "/no-such-route", body: { points: cubic } }] }],
  ["/batch", "an item naming the batch", { requests: [{ path: "/batch", body: { requests: [] } }] }],
  ["/batch", "an item with another route's body", { requests: [{ path: "/classify", body: { points: segment, t: 0.5 } }] }],
];

// [route, why, body]: bodies the service takes, which the types must take too.
const kAccepted = [
  ["/length", "points null beside a path", { path: "M0 0 L3 4", points: null, interval: null }],
  ["/length", "arc_tolerance null beside points", { points: segment, arc_tolerance: null }],
  ["/evaluate", "t null beside samples", { points: segment, samples: 3, t: null }],
  ["/flatten", "arc_tolerance with a path", { path: "M0 0 A1 1 0 0 1 2 0", tolerance: 0.1, arc_tolerance: 0.001 }],
  ["/polar", "neither t nor samples", { points: cubic, t0: [0.25, 0.5] }],
  ["/intersections", "one curve", { curves: [{ path: "M0 0 C4 4 0 4 4 0", points: null }] }],
  ["/intersections", "two curves", { curves: [{ points: segment }, { path: "M0 4 L3 0" }] }],
  ["/batch", "one item per kind of body", {
    requests: [{ path: "/evaluate", body: { points: cubic, samples: 2 } }, { path: "/length", body: { path: "M0 0 L3 4" } }],
  }],
];

// Functions that read what only one answer has after telling the answers apart.
const kDiscriminations = `/** A curve's answer has \`degree\`, a path's \`segment_count\`. */
export function describeLength(a: Answer<"/length", 200>): string {
  return a.segment_count !== undefined ? \`\${a.segment_lengths.length} segments\` : \`degree \${a.degree} on \${a.interval.join("..")}\`;
}
export function describeBounds(a: Answer<"/bounds", 200>): string {
  return a.segment_count !== undefined ? \`\${a.critical[0].map((c) => c.segment).join(",")}\` : \`degree \${a.degree} on \${a.interval.join("..")}\`;
}
export function describeNearest(a: Answer<"/nearest", 200>): number {
  return a.segment_count !== undefined ? a.results[0].segment : a.interval[0] + a.degree;
}
/** A path's loops, an interval's area, or a curve's loops. */
export function describeLoopArea(a: Answer<"/loop-area", 200>): number {
  if (a.segment_count !== undefined) return a.loops.reduce((n, loop) => n + loop.segments[0], a.segment_count);
  if (a.interval !== undefined) return a.signed_area + a.chord[0][0];
  return a.loops.length + a.stats.max_depth;
}
/** A path search's stats, one curve's, or two curves'. */
export function describeIntersectionStats(a: Answer<"/intersections", 200>): number {
  const stats = a.stats;
  if (stats.candidate_pairs !== undefined) return stats.candidate_pairs;
  if (stats.certification_iterations !== undefined) return stats.certification_iterations;
  return stats.iterations;
}
// @ts-expect-error a curve's member read before the answers are told apart
export const lengthDegree = (a: Answer<"/length", 200>): number => a.degree;
`;

function typeChecks() {
  const out = ["// The mistakes the types refuse."];
  kMistakes.forEach(([path, why, body], i) => {
    out.push(`// @ts-expect-error ${path}: ${why}`);
    out.push(`export const mistake_${i}: Body<${JSON.stringify(path)}> = ${literal(body)};`);
  });
  out.push("", "// What the service takes and the types take too.");
  kAccepted.forEach(([path, why, body], i) => {
    out.push(`// ${path}: ${why}`);
    out.push(`export const accepted_${i}: Body<${JSON.stringify(path)}> = ${literal(body)};`);
  });
  out.push("", kDiscriminations);
  return out.join("\n");
}

function client(examples) {
  const out = [];
  out.push(`// Generated by tests/contract/typed_client.mjs from README.md: do not edit.
import type { paths } from "./api";

// The one function of the platform used (the DOM library's fetch, declared alone so that
// the compiler reads only the ES library besides the generated types).
declare function fetch(url: string, init: { method: "POST"; headers: Record<string, string>; body: string }):
  Promise<{ status: number; json(): Promise<unknown> }>;

type Operation<P extends keyof paths> = paths[P] extends { post: infer O } ? O : never;
type Body<P extends keyof paths> =
  Operation<P> extends { requestBody: { content: { "application/json": infer B } } } ? B : never;
type Responses<P extends keyof paths> = Operation<P> extends { responses: infer R } ? R : never;
type Answer<P extends keyof paths, S extends keyof Responses<P>> =
  Responses<P>[S] extends { content: infer C } ? C[keyof C] : never;
type PostPath = { [P in keyof paths]: Operation<P> extends never ? never : P }[keyof paths];

/** POST a typed body; the answer is one of the operation's documented answers. */
export async function post<P extends PostPath>(baseUrl: string, path: P, body: Body<P>):
    Promise<Answer<P, keyof Responses<P>>> {
  const response = await fetch(baseUrl + path, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  return (await response.json()) as Answer<P, keyof Responses<P>>;
}

/** POST a body the service refuses (an error example); the answer is still typed. */
export async function postRefused<P extends PostPath>(baseUrl: string, path: P, body: unknown):
    Promise<Answer<P, keyof Responses<P>>> {
  const response = await fetch(baseUrl + path, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body),
  });
  return (await response.json()) as Answer<P, keyof Responses<P>>;
}
`);
  const sends = [];
  for (const ex of examples) {
    const name = `readme_line_${ex.line}`;
    const path = JSON.stringify(ex.path);
    const status = isProblem(ex.answer) ? ex.answer.status : 200;
    const answerType = `Answer<${path}, ${status}>`;
    out.push(`// README.md line ${ex.line}: POST ${ex.path}, answered ${status}`);
    if (status === 200) {
      out.push(`export const ${name}_request: Body<${path}> = ${literal(ex.body)};`);
      out.push(`// @ts-expect-error a member the request schema does not have`);
      out.push(`export const ${name}_request_unknown: Body<${path}> = ${literal(withUnknownMember(ex.body))};`);
      const ragged = withRaggedPoint(ex.body);
      if (ragged !== null) {
        out.push(`// @ts-expect-error a point [x, y, z] among points [x, y]`);
        out.push(`export const ${name}_request_ragged: Body<${path}> = ${literal(ragged)};`);
      }
      sends.push(`post(baseUrl, ${path}, ${name}_request)`);
    } else {
      out.push(`export const ${name}_request: unknown = ${literal(ex.body)};`);
      sends.push(`postRefused(baseUrl, ${path}, ${name}_request)`);
    }
    out.push(`export const ${name}_answer: ${answerType} = ${literal(ex.answer)};`);
    out.push(`// @ts-expect-error a member the answer schema does not have`);
    out.push(`export const ${name}_answer_unknown: ${answerType} = ${literal(withUnknownMember(ex.answer))};`);
    out.push("");
  }
  out.push(typeChecks());
  out.push(`/** Sends every README example, in the README's order. */
export async function sendReadmeExamples(baseUrl: string): Promise<unknown[]> {
  return [
${sends.map((s) => `    await ${s},`).join("\n")}
  ];
}
`);
  return out.join("\n");
}

const [readmePath] = process.argv.slice(2);
if (!readmePath) {
  process.stderr.write("usage: node typed_client.mjs README.md > client.ts\n");
  process.exit(2);
}
const examples = readmeExamples(readFileSync(readmePath, "utf8"));
if (examples.length < 3) {
  process.stderr.write(`${readmePath}: found ${examples.length} curl examples with a body; expected the README's examples\n`);
  process.exit(1);
}
process.stdout.write(client(examples));
