// Names inside a hand-in: a zip entry's name decoded (UTF-8 when the zip says so with bit 11 of its
// flags; otherwise the IBM PC code page, CP437 in the zip format's words, CP850 as Windows writes it
// in Western Europe), the path it may be written to
// (never outside the hand-in's folder: no "..", no absolute path, no drive letter), and the
// files every zip tool adds that are not the student's (__MACOSX/, .DS_Store, Thumbs.db).

// The upper half (0x80 to 0xFF) of CP850, the IBM PC code page Windows uses for zip names in
// Western Europe (Denmark included). The zip format names CP437; CP850 is CP437 with ø Ø where
// CP437 has ¢ ¥ (CP437 has no ø), and accented capitals where CP437 draws boxes, so æ Æ å Å é ü ß
// come out alike either way and ø comes out right only this way.
const CP850 = 'ÇüéâäàåçêëèïîìÄÅÉæÆôöòûùÿÖÜø£Ø×ƒáíóúñÑªº¿®¬½¼¡«»░▒▓│┤ÁÂÀ©╣║╗╝¢¥┐└┴┬├─┼ãÃ╚╔╩╦╠═╬¤ðÐÊËÈıÍÎÏ┘┌█▄¦Ì▀ÓßÔÒõÕµþÞÚÛÙýÝ¯´\u00ad±‗¾¶§÷¸°¨·¹³²■\u00a0';
const utf8 = new TextDecoder('utf-8', { fatal: true });

/** IBM PC code page bytes (CP850, the CP437 of Western Europe) as text. */
export function fromCp850(bytes) {
  let s = '';
  for (const c of bytes) s += c < 0x80 ? String.fromCharCode(c) : CP850[c - 0x80];
  return s;
}

/**
 * A zip entry's name: UTF-8 when `utf8Flag` (bit 11) is set; otherwise CP850 (CP437's letters and
 * ø Ø), unless the bytes are valid UTF-8 with a non-ASCII character (macOS's Archive Utility writes
 * UTF-8 without the flag; code page text is almost never valid UTF-8: "æ" is 0x91, a lone
 * continuation byte).
 */
export function decodeName(bytes, utf8Flag) {
  if (utf8Flag) return new TextDecoder('utf-8').decode(bytes);
  if (bytes.some((c) => c >= 0x80)) {
    try {
      return utf8.decode(bytes);
    } catch {
      return fromCp850(bytes);
    }
  }
  return fromCp850(bytes);
}

/** Files and folders no student made: macOS's resource forks and folder settings, Windows' thumbnails. */
export function isJunk(segments) {
  return segments.some((s) => s === '__MACOSX' || s === '.DS_Store' || s.startsWith('._') || /^thumbs\.db$/i.test(s) || /^desktop\.ini$/i.test(s));
}

/**
 * The path segments `name` may be written to inside a hand-in's folder, or { unsafe: reason }:
 * backslashes count as separators (zips made on Windows), "." and empty segments are dropped,
 * and a name that is absolute, has a drive letter or a ".." segment is refused, never repaired.
 * Characters Windows does not allow in a file name become "_".
 */
export function safeSegments(name) {
  const n = name.replace(/\\/g, '/');
  if (n.startsWith('/')) return { unsafe: 'an absolute path' };
  if (/^[A-Za-z]:/.test(n)) return { unsafe: 'a drive letter' };
  if (n.includes('\0')) return { unsafe: 'a NUL character' };
  const segments = n.split('/').filter((s) => s && s !== '.');
  if (segments.includes('..')) return { unsafe: 'a ".." that climbs out of the hand-in' };
  if (!segments.length) return { unsafe: 'an empty name' };
  // (and a name Windows keeps for a device, CON, NUL, COM1, ..., gets a "_" before it)
  // eslint-disable-next-line no-control-regex
  return { segments: segments.map((s) => s.replace(/[<>:"|?*\u0000-\u001f]/g, '_').replace(/[. ]+$/, (m) => (m.length === s.length ? '_' : '')).replace(/^(con|prn|aux|nul|com\d|lpt\d)(\.|$)/i, '_$1$2')) };
}

/** `name` (a file name) made distinct from `taken` (a Set): "a.html", "a (2).html", ... */
export function distinct(name, taken) {
  if (!taken.has(name)) return name;
  const m = /^(.*?)(\.[^.]*)?$/.exec(name);
  for (let k = 2; ; k++) {
    const c = `${m[1]} (${k})${m[2] || ''}`;
    if (!taken.has(c)) return c;
  }
}
