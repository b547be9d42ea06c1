// The class list the course site exports (--roster FILE), for the ids a grade import is keyed on
// and a download does not carry: Brightspace's download names a student by the internal user id,
// its grade import wants the OrgDefinedId or Username; Moodle's download gives a participant id,
// its grade import maps on the ID number or the email address. The roster is the site's own
// export (Brightspace: Grades → Export with OrgDefinedId, Username, names; Canvas: the gradebook
// export; Moodle: Grades → Export → plain text, with ID number and email), CSV or TSV. A student
// is matched on the user id where the roster has it (Canvas's ID), else on the full name, never
// on a folder's name.
import { readTable } from '../files/csv.js';


// a roster's columns, by the names each site exports them under
const COLUMNS = {
  orgDefinedId: /^org ?defined ?id$/i, username: /^user ?name$/i, firstName: /^first ?name$/i, lastName: /^(last ?name|surname)$/i,
  fullName: /^(student|name|full ?name)$/i, email: /^e-?mail( address)?$/i, idNumber: /^id ?number$/i, canvasId: /^id$/i,
  sisUserId: /^sis user id$/i, sisLoginId: /^sis login id$/i, section: /^section$/i,
};
const squash = (s) => String(s || '').toLowerCase().normalize('NFC').replace(/[^\p{L}\p{N}]/gu, '');

/** The roster's students (CSV or TSV text): [{ orgDefinedId, username, email, idNumber, canvasId, ..., names: [forms of the name to match] }]. */
export function parseRoster(text) {
  const [head, ...rows] = readTable(text);
  if (!head) return [];
  const col = Object.fromEntries(
    Object.entries(COLUMNS).map(([k, re]) => [k, head.findIndex((h) => re.test(h.trim()))]),
  );
  return rows.map((cells) => {
    // (Brightspace's export writes "#" before an id, so that a spreadsheet keeps it as text)
    const get = (k) => (col[k] >= 0 ? (cells[col[k]] || '').trim().replace(/^#/, '') : '');
    const first = get('firstName'), last = get('lastName'), full = get('fullName');
    const s = Object.fromEntries(Object.keys(COLUMNS).map((k) => [k, get(k) || null]));
    // "Last, First" (Canvas), "First Last", and Canvas's download form "lastfirst"
    const commaed = /^(.*),\s*(.*)$/.exec(full);
    const swapped = commaed ? [`${commaed[2]} ${commaed[1]}`, `${commaed[1]}${commaed[2]}`] : ['', ''];
    s.names = [full, `${first} ${last}`, ...swapped, `${last}${first}`].map(squash).filter(Boolean);
    s.display = full ? (commaed ? `${commaed[2]} ${commaed[1]}` : full) : `${first} ${last}`.trim();
    return s;
  }).filter((s) => s.names.length || s.canvasId);
}

/**
 * Adds the roster's ids to each submission's identity (in place): { orgDefinedId, username, email,
 * idNumber, sisUserId, sisLoginId, section, rosterName }. Returns the names matched by no roster
 * line or by more than one.
 */
export function matchRoster(submissions, roster) {
  const unmatched = [];
  for (const s of submissions) {
    const id = s.identity;
    if (!id) continue;
    let found = id.userId ? roster.filter((r) => r.canvasId === id.userId) : [];
    if (!found.length) found = roster.filter((r) => r.names.includes(squash(id.name)));
    if (found.length !== 1) { unmatched.push(`${s.name}${found.length ? ` (${found.length} roster lines match)` : ''}`); continue; }
    const r = found[0];
    Object.assign(id, {
      orgDefinedId: r.orgDefinedId,
      username: r.username,
      email: r.email,
      idNumber: r.idNumber,
      sisUserId: r.sisUserId,
      sisLoginId: r.sisLoginId,
      section: r.section,
      rosterName: r.display,
    });
  }
  return unmatched;
}
