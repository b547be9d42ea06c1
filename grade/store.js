// What the class page has graded, kept in the browser (IndexedDB), so that a reload or a closed
// tab loses nothing: each student's rows and pictures as they end, the teacher's verdicts, and how
// often each part was begun (a part begun again and again never ended: its page took the tab down), under
// the class's key (the download's bytes and the rubric, hashed: the same download dropped again
// finds them; another download, or another rubric, does not).
const DB = 'grade-class', VERSION = 2, STUDENTS = 'students', OVERRIDES = 'overrides', BEGUN = 'begun';

let opened = null;
/** The database, opened once (null where the browser keeps none: a private window may refuse it). */
function db() {
  opened ??= new Promise((resolve) => {
    let req;
    try {
      req = indexedDB.open(DB, VERSION);
    } catch {
      resolve(null);
      return;
    }
    req.onupgradeneeded = () => {
      for (const store of [STUDENTS, OVERRIDES, BEGUN]) {
        if (!req.result.objectStoreNames.contains(store)) req.result.createObjectStore(store);
      }
    };
    req.onsuccess = () => resolve(req.result);
    req.onerror = () => resolve(null);
  });
  return opened;
}

/** One request in a transaction of `store`, its result (undefined where there is no database). */
async function request(store, mode, make) {
  const d = await db();
  if (!d) return undefined;
  return new Promise((resolve, reject) => {
    const tx = d.transaction(store, mode);
    const req = make(tx.objectStore(store));
    tx.oncomplete = () => resolve(req.result);
    tx.onerror = () => reject(tx.error);
    tx.onabort = () => reject(tx.error);
  });
}

/** The class's key: SHA-256 of the download's bytes (`parts`: its files' bytes, in order) and the rubric's text, in hexadecimal. */
export async function classKey(parts, rubricText) {
  const blob = new Blob([...parts, new TextEncoder().encode(rubricText)]);
  const digest = await crypto.subtle.digest('SHA-256', await blob.arrayBuffer());
  return Array.from(new Uint8Array(digest), (b) => b.toString(16).padStart(2, '0')).join('');
}

const studentKey = (key, name) => `${key}\n${name}`;

/** Keeps `name`'s rows and pictures ([[href, data: URL]]) of the class `key`. */
export const keepStudent = (key, name, rows, pictures) =>
  request(STUDENTS, 'readwrite', (s) => s.put({ rows, pictures }, studentKey(key, name)));

/** The students of class `key` kept so far: Map name → { rows, pictures }. */
export async function keptStudents(key) {
  const range = IDBKeyRange.bound(`${key}\n`, `${key}\n\uffff`);
  const d = await db();
  if (!d) return new Map();
  const keys = await request(STUDENTS, 'readonly', (s) => s.getAllKeys(range));
  const values = await request(STUDENTS, 'readonly', (s) => s.getAll(range));
  return new Map(keys.map((k, i) => [k.slice(key.length + 1), values[i]]));
}

/** Keeps the teacher's verdicts of class `key` ([{ student, part, verdict, note }]). */
export const keepOverrides = (key, list) => request(OVERRIDES, 'readwrite', (s) => s.put(list, key));

/** The teacher's verdicts of class `key` kept, or []. */
export const keptOverrides = async (key) => (await request(OVERRIDES, 'readonly', (s) => s.get(key))) || [];

const partKey = (key, name, part) => `${key}\n${name}\n${part}`;

/** Records that `name`'s `part` of class `key` is begun; returns how often it was begun before (and never kept). */
export async function beginPart(key, name, part) {
  const before = (await request(BEGUN, 'readonly', (s) => s.get(partKey(key, name, part)))) || 0;
  await request(BEGUN, 'readwrite', (s) => s.put(before + 1, partKey(key, name, part)));
  return before;
}
