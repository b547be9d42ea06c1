// Brightspace (D2L), the course site's adapter: its download, its grade import and its feedback zip.
//   Download (Assignments → Download): a folder a submission,
//     "<submission id>-<user id> - <First Last> - <Mon D, YYYY H:MM AM>" (the colon left out in
//     downloads since about 2020: "Oct 10, 2025 1022 AM"), and an index.html listing them;
//     older downloads put the files loose: "<same> - <original name>".
//   Grade import (Grades → Import): OrgDefinedId or Username, "<item> Points Grade", then
//     "End-of-Line Indicator" "#"; each id written "#<id>" so that a spreadsheet keeps it text
//     (leading zeros too).
//   Feedback zip: the download's folder "<submission id>-<user id> - <name> - <date>/".
import { importFile } from './points.js';
import { sourceFolder } from './source-folder.js';

const MONTHS = ['Jan', 'Feb', 'Mar', 'Apr', 'May', 'Jun', 'Jul', 'Aug', 'Sep', 'Oct', 'Nov', 'Dec'];
const NAME = new RegExp(`^(\\d+)-(\\d+) - (.+?) - ((?:${MONTHS.join('|')}) \\d{1,2}, \\d{4} \\d{1,2}:?\\d{2} [AP]M)(?: - (.+))?$`);

/** "Oct 10, 2025 1022 AM" (or "10:22 AM") as "2025-10-10T10:22" (the course site's local time), or null. */
export function brightspaceTime(text) {
  const m = /^([A-Z][a-z]{2}) (\d{1,2}), (\d{4}) (\d{1,2}):?(\d{2}) ([AP])M$/.exec(text);
  if (!m) return null;
  let h = Number(m[4]) % 12;
  if (m[6] === 'P') h += 12;
  const two = (n) => String(n).padStart(2, '0');
  return `${m[3]}-${two(MONTHS.indexOf(m[1]) + 1)}-${two(m[2])}T${two(h)}:${m[5]}`;
}

/** The import: rows keyed on OrgDefinedId (or Username when every student has one and not every OrgDefinedId is known). */
export function brightspaceCsv(rows, points) {
  const every = (key) => rows.every((s) => (s.identity || {})[key]);
  const key = every('orgDefinedId') || !every('username') ? 'orgDefinedId' : 'username';
  const column = key === 'orgDefinedId' ? 'OrgDefinedId' : 'Username';
  return importFile(rows, points, [column, `${points.item} Points Grade`, 'End-of-Line Indicator'],
    (id, total) => (id[key] ? [`#${id[key]}`, total, '#'] : `no ${column} (give --roster)`));
}

export const brightspace = {
  id: 'brightspace',
  describe: 'Brightspace (D2L) download: a folder a submission, "<submission id>-<user id> - <name> - <date time>"',
  /** What a top-level name says ({ userId, name, submissionId, time, late, rest }), or null. */
  parseTopName(top, isFile) {
    const m = NAME.exec(top);
    if (!m || (isFile && !m[5]) || (!isFile && m[5])) return null;
    return {
      submissionId: m[1],
      userId: m[2],
      name: m[3],
      time: brightspaceTime(m[4]),
      late: null,
      rest: m[5] || null,
    };
  },
  /** A file the site adds beside the hand-ins: its index.html listing them. */
  /** Why a top-level name that parseTopName refuses is left out. */
  leftOut: 'not named as brightspace names a hand-in',
  siteFile: /^index\.html?$/i,
  gradeFile: { name: 'grades-brightspace.csv', make: brightspaceCsv },
  /** Where a student's feedback file `file` goes in the zip: in the folder the download gave the hand-in. */
  feedbackPath: (s, file) => `${sourceFolder(s)}/${file}`,
};
