// Test downloads as the course sites make them, built from a folder of hand-ins (the fixture
// hand-ins, or the real ones in ../shared/handins: test data, never copied into the project): a zip writer that can write what a student's zip
// tool may (names in CP850 without the UTF-8 flag, two entries of the same name, "../", a
// symbolic link, a bomb), and the three sites' downloads around a student's files.
import { readFileSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { deflateSync } from 'fflate';

const te = new TextEncoder();
// CP850's upper half (what Windows writes in Western Europe: CP437 with ø Ø), typed apart from the grader's
const CP850_UPPER = 'ÇüéâäàåçêëèïîìÄÅÉæÆôöòûùÿÖÜø£Ø×ƒáíóúñÑªº¿®¬½¼¡«»░▒▓│┤ÁÂÀ©╣║╗╝¢¥┐└┴┬├─┼ãÃ╚╔╩╦╠═╬¤ðÐÊËÈıÍÎÏ┘┌█▄¦Ì▀ÓßÔÒõÕµþÞÚÛÙýÝ¯´\u00ad±‗¾¶§÷¸°¨·¹³²■\u00a0';
/** `text` in CP850 (the characters it has). */
export const cp850 = (text) => Uint8Array.from([...text].map((c) => (c.charCodeAt(0) < 0x80 ? c.charCodeAt(0) : 0x80 + CP850_UPPER.indexOf(c))));

// CRC-32 (the zip's checksum)
const TABLE = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(data) {
  let c = 0xffffffff;
  for (const b of data) c = TABLE[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/**
 * A zip of `entries` ([{ name (string, written as UTF-8 with bit 11 set) or nameBytes (written
 * as they are, no flag), data (Uint8Array or string), store, symlink, declared (a size to
 * declare in place of the true one: a bomb that lies) }]).
 */
export function makeZip(entries, { zip64 = false } = {}) {
  const locals = [], centrals = [];
  let offset = 0;
  for (const e of entries) {
    const nameBytes = e.nameBytes || te.encode(e.name);
    const flags = e.nameBytes ? 0 : 0x800;
    const data = typeof e.data === 'string' ? te.encode(e.data) : e.data || new Uint8Array(0);
    const packed = e.store ? data : deflateSync(data);
    const method = e.store ? 0 : 8;
    const head = (sig, size) => {
      const b = Buffer.alloc(size);
      b.writeUInt32LE(sig, 0);
      return b;
    };
    const local = head(0x04034b50, 30);
    local.writeUInt16LE(20, 4); local.writeUInt16LE(flags, 6); local.writeUInt16LE(method, 8);
    local.writeUInt32LE(crc32(data), 14); local.writeUInt32LE(packed.length, 18); local.writeUInt32LE(data.length, 22);
    local.writeUInt16LE(nameBytes.length, 26);
    const central = head(0x02014b50, 46);
    central.writeUInt16LE(e.symlink ? 0x031e : 20, 4); central.writeUInt16LE(20, 6); central.writeUInt16LE(flags, 8); central.writeUInt16LE(method, 10);
    central.writeUInt32LE(crc32(data), 16); central.writeUInt32LE(packed.length, 20); central.writeUInt32LE(e.declared ?? data.length, 24);
    central.writeUInt16LE(nameBytes.length, 28);
    central.writeUInt32LE(e.symlink ? (0o120777 << 16) >>> 0 : 0, 38);
    central.writeUInt32LE(offset, 42);
    let extra = Buffer.alloc(0);
    if (zip64) {
      // every size and the offset in the ZIP64 extra field, 0xFFFFFFFF in their own fields
      extra = Buffer.alloc(28);
      extra.writeUInt16LE(1, 0); extra.writeUInt16LE(24, 2);
      extra.writeBigUInt64LE(BigInt(e.declared ?? data.length), 4); extra.writeBigUInt64LE(BigInt(packed.length), 12); extra.writeBigUInt64LE(BigInt(offset), 20);
      for (const at of [20, 24, 42]) central.writeUInt32LE(0xffffffff, at);
      central.writeUInt16LE(28, 30);
    }
    locals.push(local, nameBytes, packed);
    centrals.push(central, nameBytes, extra);
    offset += 30 + nameBytes.length + packed.length;
  }
  const cd = Buffer.concat(centrals);
  const end = Buffer.alloc(22);
  end.writeUInt32LE(0x06054b50, 0); end.writeUInt16LE(entries.length, 8); end.writeUInt16LE(entries.length, 10);
  end.writeUInt32LE(cd.length, 12); end.writeUInt32LE(offset, 16);
  if (!zip64) return new Uint8Array(Buffer.concat([...locals, cd, end]));
  // the ZIP64 end record and its locator, and the old end record saying "see ZIP64"
  const end64 = Buffer.alloc(56), locator = Buffer.alloc(20);
  end64.writeUInt32LE(0x06064b50, 0); end64.writeBigUInt64LE(44n, 4); end64.writeUInt16LE(45, 12); end64.writeUInt16LE(45, 14);
  end64.writeBigUInt64LE(BigInt(entries.length), 24); end64.writeBigUInt64LE(BigInt(entries.length), 32);
  end64.writeBigUInt64LE(BigInt(cd.length), 40); end64.writeBigUInt64LE(BigInt(offset), 48);
  locator.writeUInt32LE(0x07064b50, 0); locator.writeBigUInt64LE(BigInt(offset + cd.length), 8); locator.writeUInt32LE(1, 16);
  end.writeUInt16LE(0xffff, 8); end.writeUInt16LE(0xffff, 10); end.writeUInt32LE(0xffffffff, 16);
  return new Uint8Array(Buffer.concat([...locals, cd, end64, locator, end]));
}

/** The files under `root`, by relative path ("a/b.js" → bytes), sorted. */
export function tree(root) {
  const out = {};
  const walk = (rel) => {
    for (const name of readdirSync(path.join(root, rel)).sort()) {
      const r = rel ? `${rel}/${name}` : name;
      if (statSync(path.join(root, r)).isDirectory()) walk(r);
      else out[r] = readFileSync(path.join(root, r));
    }
  };
  walk('');
  return out;
}

/** A hand-in's files as zip entries, under `prefix`. */
export const entriesOf = (root, prefix = '') => Object.entries(tree(root)).map(([rel, data]) => ({ name: prefix + rel, data: new Uint8Array(data) }));

/** A built download's ids for its student number `k`: the user id and the submission id (Canvas: the file's id). */
export const idsOf = (k) => ({ uid: String(640600 + k), sid: String(39700 + k) });

/** Canvas's name for a student: the sortable name ("Last, First") with all but word characters taken out, lower-cased (canvas-lms lib/content_zipper.rb). */
export const lastFirst = (name) => name.split(' ').reverse().join('').toLowerCase().replace(/[^\p{L}\p{N}_]/gu, '');

/**
 * Where `site`'s download puts `file` of student `s` ({ name, k, late }): Brightspace's folder
 * "<submission id>-<user id> - <name> - <when>/", Canvas's file "<lastfirst>[_late]_<user id>_<file
 * id>_<file>", Moodle's folder "<name>_<participant id>_assignsubmission_file/". `sid` gives
 * another submission id (an earlier hand-in), `when` another time.
 */
export function siteName(site, s, file, { sid = idsOf(s.k).sid, when = 'Oct 10, 2025 1022 AM' } = {}) {
  const { uid } = idsOf(s.k);
  if (site === 'brightspace') return `${sid}-${uid} - ${s.name} - ${when}/${file}`;
  if (site === 'canvas') return `${lastFirst(s.name)}${s.late ? '_late' : ''}_${uid}_${sid}_${file}`;
  return `${s.name}_${uid}_assignsubmission_file/${file}`;
}
