// What the command-line tools share: node:util parseArgs with --help, one kind of error for bad
// usage, which each command reports with its help text and exit code 2, and the progress line.
import { realpathSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';

/** Bad usage: an unknown option, a missing or bad value. The command exits with code 2. */
export class UsageError extends Error {}

/**
 * Reads a command's options; --help (-h) is added to them. Positional arguments are refused.
 * @param {string[]} argv the arguments after the script's name
 * @param {object} options parseArgs's option descriptions, e.g. { out: { type: 'string' } }
 * @returns {object} the options given, by name (`help: true` when --help was given)
 * @throws {UsageError} for an unknown option, a string option without a value, or a positional
 */
export function parseOptions(argv, options) {
  let values;
  try {
    ({ values } = parseArgs({ args: argv, options: { help: { type: 'boolean', short: 'h' }, ...options }, strict: true }));
  } catch (err) {
    if (typeof err.code === 'string' && err.code.startsWith('ERR_PARSE_ARGS_')) throw new UsageError(err.message);
    throw err;
  }
  for (const [name, value] of Object.entries(values)) {
    if (value === '') throw new UsageError(`--${name} needs a value`);
  }
  return values;
}

/**
 * A whole number from `min` to `max`, from an option's text.
 * @param {string} text @param {string} label the option as the user wrote it, e.g. "--width"
 * @throws {UsageError} naming the option when it is not one
 */
export function wholeNumber(text, label, min, max) {
  const n = Number(text);
  if (!Number.isInteger(n) || n < min || n > max) {
    throw new UsageError(`${label} must be a whole number from ${min} to ${max}, not ${JSON.stringify(text)}`);
  }
  return n;
}

// (the progress line lives beside the grader's, which uses it too)
export { progressLine } from '../grader/node/cli/progress-line.js';

/** Whether the module at `moduleUrl` (its import.meta.url) is the script node was started with; importing it, as a test does, runs nothing. */
export function isMainScript(moduleUrl) {
  if (!process.argv[1]) return false;
  try {
    return realpathSync(process.argv[1]) === realpathSync(fileURLToPath(moduleUrl));
  } catch {
    return false;
  }
}

/**
 * Runs a command-line tool the same way for all: the options read by `readOptions` (a UsageError
 * prints it with the help, exit code 2), --help prints the help (0), otherwise `run(options)`
 * gives the exit code; a failure prints "name: failed during <progress>: message" (1).
 * @param {{name: string, help: string, readOptions: (argv: string[]) => object, run: (opt: object) => number|Promise<number>, progress?: {last: string}}} tool
 */
export async function runCommand({ name, help, readOptions, run, progress }, argv = process.argv.slice(2)) {
  let opt;
  try {
    opt = readOptions(argv);
  } catch (err) {
    if (!(err instanceof UsageError)) throw err;
    console.error(`${name}: ${err.message}\n\n${help}`);
    return (process.exitCode = 2);
  }
  if (opt.help) {
    console.log(help);
    return (process.exitCode = 0);
  }
  try {
    return (process.exitCode = await run(opt));
  } catch (err) {
    if (progress) process.stderr.write('\n');
    console.error(`${name}: ${progress?.last ? `failed during "${progress.last}": ` : ''}${err.message}`);
    return (process.exitCode = 1);
  }
}
