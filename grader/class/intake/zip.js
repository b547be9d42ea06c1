// Reading a zip as the grader's intake needs it, and nothing more: its entries from the central
// directory (every entry, two of the same name too; ZIP64 too, as a large download is written), each name decoded as the zip says (bit 11:
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

const u64 = (b, o) => u32(b, o) + u32(b, o + 4) * 2 ** 32;

/** The data of the ZIP64 extra field among the `length` bytes of extra fields at `o`, or null. */
function zip64Extra(b, o, length) {
  for (let at = o; at + 4 <= o + length;) {
    const id = u16(b, at), size = u16(b, at + 2);
    if (id === 1) return b.subarray(at + 4, at + 4 + size);
    at += 4 + size;
  }
  return null;
}

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
  let count = u16(b, end + 10), cdOffset = u32(b, end + 16);
  if (count === 0xffff || cdOffset === 0xffffffff) {
    // ZIP64 (a large download): the locator just before the end record points at the ZIP64 end record
    const loc = end - 20;
    if (loc < 0 || u32(b, loc) !== 0x07064b50) throw new IntakeError('its ZIP64 end record is missing');
    const end64 = u64(b, loc + 8);
    if (end64 + 56 > b.length || u32(b, end64) !== 0x06064b50) throw new IntakeError('its ZIP64 end record is damaged');
    count = u64(b, end64 + 32);
    cdOffset = u64(b, end64 + 48);
  }
  const entries = [];
  let o = cdOffset;
  for (let k = 0; k < count; k++) {
    if (o + 46 > b.length || u32(b, o) !== 0x02014b50) throw new IntakeError(`its central directory is damaged at entry ${k + 1} of ${count}`);
    const flags = u16(b, o + 8), method = u16(b, o + 10);
    let compressedSize = u32(b, o + 20), size = u32(b, o + 24);
    const nameLength = u16(b, o + 28), extraLength = u16(b, o + 30), commentLength = u16(b, o + 32);
    const madeBy = u16(b, o + 4) >> 8, external = u32(b, o + 38);
    let offset = u32(b, o + 42);
    if (size === 0xffffffff || compressedSize === 0xffffffff || offset === 0xffffffff) {
      // the ZIP64 extra field (id 1) holds, in this order, each value its 32-bit field could not
      const z = zip64Extra(b, o + 46 + nameLength, extraLength);
      if (!z) throw new IntakeError(`its entry ${k + 1} says ZIP64 but has no ZIP64 field`);
      let at = 0;
      if (size === 0xffffffff) { size = u64(z, at); at += 8; }
      if (compressedSize === 0xffffffff) { compressedSize = u64(z, at); at += 8; }
      if (offset === 0xffffffff) offset = u64(z, at);
    }
    const name = decodeName(b.subarray(o + 46, o + 46 + nameLength), (flags & 0x800) !== 0);
    // a symbolic link: a Unix mode of S_IFLNK in the high half of the external attributes
    const symlink = madeBy === 3 && ((external >>> 16) & 0o170000) === 0o120000;
    const encrypted = (flags & 1) !== 0;
    entries.push({ name, dir: /[/\\]$/.test(name), symlink, method, size, compressedSize, encrypted, offset });
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
