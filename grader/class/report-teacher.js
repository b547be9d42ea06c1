// What the report adds for the teacher's loop: who a hand-in is (the course site's name and ids,
// its time, late, the earlier hand-ins and what the intake left out) and, on a part the teacher
// set, the teacher's verdict marked as such with the grader's beside it.
import { esc } from '../files/html.js';

const SITE = { brightspace: 'Brightspace', canvas: 'Canvas', moodle: 'Moodle', folders: 'a folder' };

/** A student's identity as the course site gave it, the earlier hand-ins and the intake's notes (or nothing). */
export function identityHtml(s) {
  const id = s.identity;
  if (!id) return '';
  const facts = [
    `from ${SITE[id.site] || id.site}${id.source && id.source.length ? ` (${esc(id.source.join(', '))})` : ''}`,
    id.userId && `user id ${esc(id.userId)}`, id.submissionId && `submission ${esc(id.submissionId)}`, id.orgDefinedId && `OrgDefinedId ${esc(id.orgDefinedId)}`,
    id.time && `handed in ${esc(id.time.replace('T', ' '))}`, id.late === true ? '<strong>late</strong>' : id.late === false ? 'on time' : '',
  ].filter(Boolean);
  const earlier = (s.earlier || []).map((e) => {
    const when = esc(e.time ? e.time.replace('T', ' ') : 'no time');
    const submission = e.submissionId ? `, submission ${esc(e.submissionId)}` : '';
    const files = `${e.files} file${e.files === 1 ? '' : 's'}`;
    return `<li>${when}${e.late ? ' (late)' : ''}${submission}: ${esc((e.source || []).join(', '))} (${files}; not graded)</li>`;
  });
  return `<p class="identity">${facts.join(' · ')}</p>` +
    (earlier.length ? `<p>Handed in earlier (the latest is graded):</p><ul class="earlier">${earlier.join('')}</ul>` : '') +
    (s.intakeNotes && s.intakeNotes.length ? `<p>Unpacking:</p><ul class="notes">${s.intakeNotes.map((n) => `<li>${esc(n)}</li>`).join('')}</ul>` : '');
}

/** After a part's verdict badge: "set by the teacher (the grader: fail)", and the note to the student. */
export function teacherMark(r, detail = false) {
  if (!r.teacher) return '';
  const mark = `<span class="teacher" title="set by the teacher in overrides.tsv">teacher</span><span class="grader-said">grader: ${esc(r.grader.verdict)}</span>`;
  return detail ? `${mark}${r.teacher.note ? `<span class="teacher-note">note to the student: ${esc(r.teacher.note)}</span>` : ''}` : mark;
}

export const TEACHER_CSS = `.teacher{display:inline-block;margin-left:.3rem;padding:0 .3rem;border:1px solid #1d2330;border-radius:.3rem;font-size:.7rem;font-weight:600}
.grader-said{margin-left:.3rem;font-size:.7rem;color:#556}.teacher-note{display:block;font-size:.85rem;font-weight:normal}.identity{color:#334}
.items td,.items th{font-size:.85rem}.items tr.fail td:first-child{border-left:4px solid #b3261e}.items tr.review td:first-child{border-left:4px solid #a66b00}.items tr.pass td:first-child{border-left:4px solid #2a7d2a}`;
