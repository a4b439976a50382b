// The message a person reads for a thrown value: the core's errors are `Error`s whose message
// names the offending field by its path in the scenario format (`params.avoid_radius`,
// `robots[2].goal`); the page names it as the panels do (R_c, robot 3: robots and obstacles
// are numbered from 1 on the page, from 0 in the file).

/**
 * The page's name of each parameter by its key (`avoid_radius` → `R_c`): the core's table,
 * given by wasm-views.js once the module is loaded (useParameters); a key without one keeps
 * its own name.
 * @type {Map<string, string>}
 */
const LABELS = new Map();

/** Takes the page's names from the core's parameter table (`parameters().rows`). */
export function useParameters(rows) {
  for (const { name, symbol } of rows) LABELS.set(name, symbol);
}

/** `text` with the scenario's field paths put as the page shows them. */
export function humanize(text) {
  return String(text)
    .replace(/params\.(\w+)/g, (_m, key) => LABELS.get(key) ?? key)
    .replace(/\b(robots|obstacles)\[(\d+)\](\.(\w+))?/g, (_m, list, i, _dot, field) => {
      const name = `${list === 'robots' ? 'robot' : 'obstacle'} ${Number(i) + 1}`;
      return field ? `${name}'s ${field}` : name;
    })
    .replace(/\b([a-z]+_[a-z_]+)\b/g, (_m, key) => LABELS.get(key) ?? key);
}

/** The message of `e`, as the page names things. */
export function messageOf(e) {
  return humanize(e?.message ?? String(e));
}
