// The message a person reads for a thrown value: the core's errors are `Error`s whose message
// names the offending field by its path in the scenario format (`params.avoid_radius`,
// `robots[2].goal`); the page names it as the panels do (R_c, robot 3: robots and obstacles
// are numbered from 1 on the page, from 0 in the file).

/** The page's label of each parameter and scenario field the panels edit (params.js). */
export const FIELD_LABELS = {
  k_v: 'k_v',
  k_omega: 'k_ω',
  k_a: 'k_a',
  transition_width: 'ε',
  avoid_speed: 'v_c',
  avoid_radius: 'R_c',
  safe_radius: 'r_ij',
  sense_radius: 'R_s',
  v_max: 'v_max',
  omega_max: 'ω_max',
  barrier_rate: 'α',
  tol_position: 'tol_p',
  tol_heading: 'tol_θ',
  align_fade: 'align_fade',
  avoidance: 'avoidance',
};

/** `text` with the scenario's field paths put as the page shows them. */
export function humanize(text) {
  return String(text)
    .replace(/params\.(\w+)/g, (_m, key) => FIELD_LABELS[key] ?? key)
    .replace(/\b(robots|obstacles)\[(\d+)\](\.(\w+))?/g, (_m, list, i, _dot, field) => {
      const name = `${list === 'robots' ? 'robot' : 'obstacle'} ${Number(i) + 1}`;
      return field ? `${name}'s ${field}` : name;
    })
    .replace(/\b([a-z]+_[a-z_]+)\b/g, (_m, key) => FIELD_LABELS[key] ?? key);
}

/** The message of `e`, as the page names things. */
export function messageOf(e) {
  return humanize(e?.message ?? String(e));
}
