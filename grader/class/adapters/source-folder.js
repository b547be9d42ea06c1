// Where a course site's download put a student's hand-in: the first folder (or loose-file prefix)
// the intake took it from, which a site whose feedback zip is keyed by that folder writes back to.

/** The folder the download gave the hand-in of `s` (a row of the class: its `identity.source`), without a trailing slash; '' where none is known. */
export const sourceFolder = (s) => ((s.identity && s.identity.source && s.identity.source[0]) || '').replace(/\/$/, '');
