// A submission's name as a file or folder name on any OS (no Node: the class's outputs, built in
// Node and in a page alike, name their files with it; grader/files/layout.js gives it to the rest).

// names Windows keeps for devices, in any letter case and with any extension ("con.txt" too)
const RESERVED = /^(con|prn|aux|nul|com[0-9¹²³]|lpt[0-9¹²³])(\.|$)/i;

/**
 * A submission's name as a file or folder name on any OS: its letters (æøå too) and digits, '.',
 * '-' and '_' kept, every other run of characters '_'; never '.', '..', hidden, ending in '.' or a
 * Windows device name ("CON").
 */
export function safeName(name) {
  let s = String(name).normalize('NFC').replace(/[^\p{L}\p{N}._-]+/gu, '_').replace(/^\.+/, (dots) => '_'.repeat(dots.length)).replace(/\.+$/, '');
  if (!s) s = '_';
  return RESERVED.test(s) ? `_${s}` : s;
}
