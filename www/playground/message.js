// The message a person reads for a thrown value: the core's errors are `Error`s whose message
// names the offending field.

/** The message of `e`. */
export function messageOf(e) {
  return e?.message ?? String(e);
}
