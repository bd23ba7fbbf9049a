// Calls to the service's own JSON API. Every error comes back as an ApiError that
// carries the RFC 9457 problem the service sent (type, title, status, detail, errors),
// so the page can show it as it is instead of swallowing it.

/** An answer other than 200: the service's problem details, or a network failure. */
export class ApiError extends Error {
  constructor(route, status, problem) {
    super(`${route}: ${status} ${problem.title ?? ''}`.trim());
    this.route = route;
    this.status = status;  // 0 when the request never got an answer
    this.problem = problem;  // {type, title, status, detail, errors?}
  }
}

const kTokenKey = 'bezier-service-token';
let memoryToken = '';  // used when sessionStorage is unavailable

/** The bearer token the user entered (only needed when the service requires one). */
export function apiToken() {
  try {
    return sessionStorage.getItem(kTokenKey) ?? '';
  } catch {
    return '';
  }
}

export function setApiToken(token) {
  try {
    if (token) sessionStorage.setItem(kTokenKey, token);
    else sessionStorage.removeItem(kTokenKey);
  } catch {
    // Storage may be disabled (private mode): the token then lasts until reload only.
  }
  memoryToken = token;
}

/**
 * POST `body` as JSON to `route` (e.g. '/evaluate') and return the parsed answer.
 * Throws ApiError for every non-200 answer, with the problem details the service sent
 * (or a synthesised one when the body is not a problem, e.g. a proxy's HTML page).
 */
export async function post(route, body) {
  const headers = {'Content-Type': 'application/json', 'Accept': 'application/json'};
  const token = apiToken() || memoryToken;
  if (token) headers['Authorization'] = `Bearer ${token}`;
  let response;
  try {
    response = await fetch(route, {method: 'POST', headers, body: JSON.stringify(body)});
  } catch (e) {
    throw new ApiError(route, 0, {title: 'Network error', detail: String(e.message ?? e)});
  }
  const text = await response.text();
  let parsed = null;
  try {
    parsed = JSON.parse(text);
  } catch {
    parsed = null;
  }
  if (response.ok && parsed !== null) return parsed;
  if (parsed !== null && typeof parsed === 'object' && 'status' in parsed) {
    throw new ApiError(route, response.status, parsed);
  }
  throw new ApiError(route, response.status, {
    title: response.statusText || 'Unexpected answer',
    status: response.status,
    detail: text.slice(0, 300),
  });
}
