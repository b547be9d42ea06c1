// The command node tools/reference.js: --help, exit codes, messages without a stack, the PNG it
// writes and the JSON of --compare; importing it runs nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { PNG } from 'pngjs';
import { lit } from './reference-scenes.js';

const TOOL = fileURLToPath(new URL('../../tools/reference.js', import.meta.url));

test('the command: --help, bad usage, errors without a stack, --compare prints JSON', () => {
  const run = (...args) => spawnSync(process.execPath, [TOOL, ...args], { encoding: 'utf8' });
  const help = run('--help');
  assert.equal(help.status, 0);
  assert.match(help.stdout, /usage: node tools\/reference\.js --scene/);
  assert.equal(run().status, 2);
  assert.equal(run('--scene').status, 2);
  assert.equal(run('--bogus', 'x').status, 2);
  const dir = mkdtempSync(path.join(tmpdir(), 'reference-cli-'));
  try {
    const missing = run('--scene', path.join(dir, 'nope.json'), '--out', path.join(dir, 'x.png'));
    assert.equal(missing.status, 1);
    assert.match(missing.stderr, /cannot read the scene/);
    assert.doesNotMatch(missing.stderr, /\n\s+at /);
    const sceneFile = path.join(dir, 'scene.json');
    writeFileSync(sceneFile, JSON.stringify({ ...lit(), canvas: { width: 40, height: 30 } }));
    const out = path.join(dir, 'ref.png');
    const made = run('--scene', sceneFile, '--out', out);
    assert.equal(made.status, 0, made.stderr);
    const png = PNG.sync.read(readFileSync(out));
    assert.deepEqual([png.width, png.height], [40, 30]);
    const compared = run('--scene', sceneFile, '--out', out, '--compare', out);
    assert.equal(compared.status, 0, compared.stderr);
    const stats = JSON.parse(compared.stdout);
    assert.equal(stats.silhouetteMismatch, 0);
    assert.ok(stats.rmse <= 0.5 / 255);
    const wrongSize = run('--scene', sceneFile, '--width', '20', '--height', '20', '--compare', out);
    assert.equal(wrongSize.status, 1);
    assert.match(wrongSize.stderr, /40×30 but the reference is 20×20/);
    assert.doesNotMatch(wrongSize.stderr, /\n\s+at /);
    assert.equal(run('--scene', sceneFile, '--width', '-3', '--out', out).status, 2);
    // a script that imports the module runs none of the command: no output, exit code 0
    const importer = path.join(dir, 'importer.mjs');
    writeFileSync(importer, `import ${JSON.stringify(pathToFileURL(TOOL).href)};\n`);
    const imported = spawnSync(process.execPath, [importer], { encoding: 'utf8' });
    assert.deepEqual([imported.status, imported.stdout, imported.stderr], [0, '', '']);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
});
