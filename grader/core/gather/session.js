// One part's gathering: the page interface, the rubric, and what has been seen so far (the
// artifact: plain facts and named pictures). Every step of the gatherers goes through here: a
// frame runs only by `tick` (a count of frames, never a clock's reading), a picture is taken by
// `shot`, a control is used by `press` and its effect on the picture read by `trial`. The wall
// clock is an outer bound only: past `deadline` a step throws TooSlow. The page's own work over the
// gathering (vertices, and draw calls at drawCallWork each) is bounded by a count, the rubric's
// gatherWork: past it a frame throws TooHeavy, at the same step on every machine.
import { recording } from './reads.js';
import { analyse, pictureChange } from '../measure.js';
import { describe, effectOf } from '../controls.js';
import { HUNDREDTHS, MS_PER_SECOND } from '../units.js';

/** A real wait between looks at the page's promises (settle): never a bound on what a page shows. */
const SETTLE_POLL_MS = 10;

/** The wall clock's outer bound ran out while `doing`. */
export class TooSlow extends Error {
  constructor(doing) {
    super(`too slow to judge here, while ${doing}`);
    this.doing = doing;
  }
}

/** The page's own work over the gathering (`work`) passed the rubric's gatherWork while `doing`. */
export class TooHeavy extends TooSlow {
  constructor(doing, work) {
    super(doing);
    this.message = `too heavy to judge here, while ${doing}`;
    this.work = work;
  }
}

/** What the gathering is doing until the page's first frame is seen (past it, the page draws): the step it starts in. */
export const FIRST_FRAME = 'waiting for the first frame';

/** The page has drawn a frame (`s`: the page's state(): draw calls, and a WebGPU frame presented). */
export const drewAFrame = (s) => s.draws > 0 && (s.api !== 'webgpu' || s.frames > 0);

export const effectWords = {
  finer: 'the silhouette got rounder', coarser: 'the silhouette got coarser', starts: 'the picture started moving', stops: 'the picture stopped moving',
  shading: 'the shading changed, not the silhouette', blank: 'the picture went blank', none: 'nothing visible changed', unclickable: 'could not be used',
};

/** Adds `ms` to the step `what` of `steps` ({ step: ms }). */
export function addStep(steps, what, ms) {
  steps[what] = (steps[what] || 0) + ms;
}

/**
 * A clock of the gathering's steps: mark(what) counts the time since the last mark (from the
 * first step, FIRST_FRAME) to that one in `steps` ({ step: ms }), and counts from now to `what`
 * (null: to none).
 */
function stepClock(steps) {
  let marked = FIRST_FRAME, since = Date.now();
  return (what) => {
    const now = Date.now();
    if (marked !== null) addStep(steps, marked, now - since);
    marked = what;
    since = now;
  };
}

/**
 * A gathering session over `page` (the page interface) for `part`. `progress(text)` hears each
 * step; `deadline` (ms since the epoch) is the outer bound; `steps` ({ step: ms }) hears how long
 * each step took, a step named by step() or, where it is said to nobody, by mark() (read by no
 * gatherer: where the time goes, for the benchmark).
 */
export function openSession(page, { part, rubric, progress = () => {}, deadline = Infinity, steps = {} }) {
  const mark = stepClock(steps);
  // every threshold and control pattern the gathering reads, with its value (reads.js)
  const gatheredWith = { [`parts.${part}.must`]: (rubric.parts[part] || {}).must };
  const thresholds = recording(rubric.thresholds, gatheredWith);
  const facts = {
    part, api: null, canvas: null, tooSlow: null,
    actions: [], roles: {}, controls: [], trials: [], views: [], ladder: [], sliders: [],
    work: { frames: 0, draws: 0, vertices: 0 }, gatheredWith,
  };
  const session = {
    page, rubric, thresholds, patterns: recording(rubric.controls, gatheredWith, 'controls.'), part, facts,
    must: new Set((rubric.parts[part] || {}).must || []),
    images: {}, // name → { width, height, data }
    cur: null, // the picture as it is now: { img, an }
    moving: false, // does the picture move by itself now?
    effects: new Map(), // control index → the effect seen when it was tried
    taken: new Set(), // controls given a role
    roles: {}, // role → control
    trialsMade: 0,
    values: new Map(), // control index → the value we left it at (a slider lowered to make the shading visible stays lowered)
    // what a frame of this page costs, in its own work (vertices, and draw calls at drawCallWork
    // vertices each), from the last frames run; and its vertices alone (what a level changes)
    frameWork: 0, frameVertices: 0,
    // the page's draws an animation frame and its animation loops, from the last frames run (the clock's
    // count of frames, where the driver has it): { loops, draws } or null
    frameDraws: null,
    animationFrames: 0,
    doing: FIRST_FRAME,

    /** A step of the gathering begun: timed from here (mark), said (progress), and named if it runs out of time. */
    step(what) { mark(what); session.doing = what; progress(what); },
    mark,
    outOfTime() {
      if (Date.now() > deadline) throw new TooSlow(session.doing);
    },
    /** A jump (the frame it fires draws a change made in a handler), then `frames` more at 60 Hz. */
    async tick(ms, frames = 0) {
      session.outOfTime();
      const s = await page.tick(ms, frames); // (the state the frames left)
      const w = facts.work;
      const n = frames + 1, v = (s.vertices - w.vertices) / n;
      Object.assign(session, { frameVertices: v, frameWork: v + (thresholds.drawCallWork * (s.draws - w.draws)) / n });
      const a = s.animation, ran = a ? a.count - session.animationFrames : 0;
      if (ran > 0) {
        const perFrame = (HUNDREDTHS * (s.draws - w.draws)) / ran;
        session.frameDraws = { loops: a.loops, draws: Math.round(perFrame) / HUNDREDTHS };
      }
      if (a) session.animationFrames = a.count;
      Object.assign(w, { frames: w.frames + frames + 1, draws: s.draws, vertices: s.vertices });
      const spent = w.vertices + thresholds.drawCallWork * w.draws;
      if (spent > thresholds.gatherWork) throw new TooHeavy(session.doing, spent);
    },
    /** What the page awaits in real time (fetches, WebGPU requests), waited for within firstFrameSeconds; no frame runs meanwhile. */
    async settle() {
      const until = Date.now() + rubric.firstFrameSeconds * MS_PER_SECOND;
      for (;;) {
        const s = await page.state();
        if (!s.pending || Date.now() > until) return s;
        await new Promise((resolve) => setTimeout(resolve, SETTLE_POLL_MS));
      }
    },
    async shot() {
      const img = await page.snap();
      return img && { img, an: analyse(img, thresholds) };
    },
    /** Keeps a picture in the artifact under `name`; returns the name. */
    keep(name, img) {
      session.images[name] = img;
      return name;
    },
    /** Sets a value control and remembers it as where the page now stands. */
    async set(c, value, events = ['input', 'change']) {
      await page.setValue(c, value, events);
      session.values.set(c.index, value);
    },
    /** A value control's value as we left it (else as the page had it). */
    now(c) {
      return session.values.has(c.index) ? session.values.get(c.index) : c.value;
    },
    act(text) {
      facts.actions.push(text);
    },
    /**
     * Gives control `c` the role `role` (the first found keeps it), with what showed it (`found`, a
     * word of computed/roles.js, and `more`: another control that took part). facts.roles: the
     * control, its description and listeners, what showed it; the audits put them in words.
     */
    assign(role, c, found, more = {}) {
      if (session.roles[role]) return;
      session.roles[role] = c;
      session.taken.add(c.index);
      facts.roles[role] = { control: c.index, what: describe(c), listens: c.events || [], found, ...more };
    },
  };
  return Object.assign(session, trials(session));
}

/** The session's trials: a click, an action tried and what it did to the picture, the picture watched for motion. */
function trials(session) {
  const { page, thresholds, facts } = session;
  return {
    async press(c, what) {
      const r = await page.click(c);
      if (!r.ok) {
        session.act(`could not click ${what} ${describe(c)}: ${r.why}`);
        return false;
      }
      session.act(`clicked ${what} ${describe(c)}`);
      await session.tick(session.thresholds.actionTickMs);
      return true;
    },
    /** Tries one action from the state as it is and says what it did to the picture. */
    async trial(act, { watchMotion = true } = {}) {
      const before = session.cur;
      if (!await act()) return 'unclickable';
      const after = await session.shot();
      if (!after) return 'none';
      let later = after;
      if (watchMotion || session.moving) {
        await session.tick(thresholds.trialTickMs, thresholds.trialFrames); // trialFrames + 1 frames: an orbit a small step a frame shows it moved
        later = await session.shot();
      }
      const effect = effectOf({ before, after, later, wasMoving: session.moving }, thresholds);
      session.cur = later;
      if (effect === 'starts') session.moving = true;
      if (effect === 'stops') session.moving = false;
      return effect;
    },
    async tryClick(c, what, opts) {
      const effect = await session.trial(() => session.press(c, what), opts);
      if (effect !== 'unclickable') {
        session.effects.set(c.index, effect);
        facts.trials.push({ control: c.index, effect });
        session.act(`  → ${effectWords[effect]}`);
      }
      return effect;
    },
    /** Does the picture move by itself over three frames? */
    async watch() {
      await session.tick(thresholds.watchTickMs, thresholds.watchFrames);
      const next = await session.shot();
      session.moving = pictureChange(session.cur.img, next.img, thresholds) > thresholds.pictureMoves;
      session.cur = next;
      return session.moving;
    },
  };
}
