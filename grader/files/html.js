// Text put into an HTML page the grader writes (the report, its teacher marks and item analysis,
// the labels' table, a student's feedback page, the similarity report): every value from a hand-in
// or a course site escaped, in one place.

/** `s` as text for HTML content or a quoted attribute: & < > " ' as entities. */
export const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
