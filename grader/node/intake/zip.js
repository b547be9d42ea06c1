// Reading a zip as the grader's intake needs it, and nothing more: its entries from the central
// directory (every entry, two of the same name too), each name decoded as the zip says (bit 11:
// UTF-8; otherwise the IBM PC code page, CP850: names.js), and each entry inflated by
// fflate's streaming Inflate with a cap, so that a zip bomb stops at the bound instead of filling
// the memory (fflate's unzipSync keys entries by name, decodes other names as Latin-1 and
// trusts the declared sizes). Plain data in, plain data out: no files are written here.
import { Inflate } from 'fflate';
import { decodeName } from './names.js';

/** An intake error: the message is for the teacher, about this one hand-in. */
export class IntakeError extends Error {}

const u16 = (b, o) => b[o] | (b[o + 1] << 8);
const u32 = (b, o) => (b[o] | (b[o + 1] << 8) | (b[o + 2] << 16) | (b[o + 3] << 24)) >>> 0;

/** Where the end-of-central-directory record starts (searched from the end, past a comment). */
function endRecord(b) {
  for (let o = b.length - 22; o >= Math.max(0, b.length - 22 - 0xffff); o--) {
    if (u32(b, o) === 0x06054b50) return o;
  }
  throw new IntakeError('it is not a zip file (no central directory: cut short or another format)');
}

/**
 * The entries of zip `bytes`: [{ name, dir, symlink, method, size, compressedSize, encrypted, offset }],
 * in the order of the central directory. `name` is decoded (UTF-8 or CP850), as the zip stores it.
 */
export function zipEntries(bytes) {
  const b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const end = endRecord(b);
  const count = u16(b, end + 10), cdOffset = u32(b, end + 16);
  if (count === 0xffff || cdOffset === 0xffffffff) throw new IntakeError('it is a ZIP64 archive (over 4 GB or 65,535 entries), which the grader does not read');
  const entries = [];
  let o = cdOffset;
  for (let k = 0; k < count; k++) {
    if (o + 46 > b.length || u32(b, o) !== 0x02014b50) throw new IntakeError(`its central directory is damaged at entry ${k + 1} of ${count}`);
    const flags = u16(b, o + 8), method = u16(b, o + 10);
    const compressedSize = u32(b, o + 20), size = u32(b, o + 24);
    const nameLength = u16(b, o + 28), extraLength = u16(b, o + 30), commentLength = u16(b, o + 32);
    const madeBy = u16(b, o + 4) >> 8, external = u32(b, o + 38), offset = u32(b, o + 42);
    const name = decodeName(b.subarray(o + 46, o + 46 + nameLength), (flags & 0x800) !== 0);
    // a symbolic link: a Unix mode of S_IFLNK in the high half of the external attributes
    const symlink = madeBy === 3 && ((external >>> 16) & 0o170000) === 0o120000;
    entries.push({ name, dir: /[/\\]$/.test(name), symlink, method, size, compressedSize, encrypted: (flags & 1) !== 0, offset });
    o += 46 + nameLength + extraLength + commentLength;
  }
  return entries;
}

/**
 * The bytes of `entry` of zip `bytes`, inflated; at most `cap` bytes come out (an IntakeError past
 * it, whatever size the entry declares). Throws an IntakeError for what cannot be read.
 */
export function entryData(bytes, entry, cap) {
  const b = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const o = entry.offset;
  if (o + 30 > b.length || u32(b, o) !== 0x04034b50) throw new IntakeError(`"${entry.name}" is damaged (no local header where the directory says)`);
  if (entry.encrypted) throw new IntakeError(`"${entry.name}" is encrypted (a password-protected zip)`);
  const start = o + 30 + u16(b, o + 26) + u16(b, o + 28);
  const raw = b.subarray(start, start + entry.compressedSize);
  if (raw.length < entry.compressedSize) throw new IntakeError(`"${entry.name}" is cut short`);
  if (entry.method === 0) {
    if (raw.length > cap) throw new TooBig(raw.length);
    return raw.slice();
  }
  if (entry.method !== 8) throw new IntakeError(`"${entry.name}" is compressed with method ${entry.method}, which the grader does not read (only stored and deflate)`);
  const chunks = [];
  let total = 0;
  const inflate = new Inflate((chunk) => {
    total += chunk.length;
    if (total > cap) throw new TooBig(total);
    chunks.push(chunk);
  });
  try {
    // fed in slices, so that the cap is checked as the output grows
    const STEP = 1 << 16;
    for (let k = 0; k < raw.length; k += STEP) inflate.push(raw.subarray(k, k + STEP), k + STEP >= raw.length);
    if (!raw.length) inflate.push(raw, true);
  } catch (err) {
    if (err instanceof TooBig) throw err;
    throw new IntakeError(`"${entry.name}" does not inflate (${err.message}): the zip is damaged`);
  }
  const out = new Uint8Array(total);
  let at = 0;
  for (const c of chunks) { out.set(c, at); at += c.length; }
  return out;
}

/** Thrown by entryData when an entry inflates past its cap. */
export class TooBig extends Error {
  constructor(bytes) {
    super(`more than ${bytes} bytes`);
    this.bytes = bytes;
  }
}
