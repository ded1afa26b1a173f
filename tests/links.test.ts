/**
 * Every scene of every lesson, at its first and last step, as a link: the
 * list in scene-links.json was written before the lessons moved onto the kit
 * (November 2026). Each must still open the same state (read back and written
 * again, it is the same link, with nothing ignored), and each scene must still
 * set up exactly that state. A renamed field or a moved default fails here.
 * One change since, on purpose (#19): de-casteljau, quadratic and
 * bezier-properties open at their first scene's step 0 (they opened at its
 * last step), so the first clicker press is the first step; their scene links
 * are unchanged.
 */
import { describe, expect, it } from 'vitest';
import { loadState, normalizeState } from '../src/app/lessonState';
import { lessons } from '../src/app/registry';
import { decodeState, defaultsOf, encodeState, keyOf } from '../src/app/urlState';
import recorded from './scene-links.json';

const links = recorded as Record<string, string[]>;

describe('links made before the kit', () => {
  it('name every lesson of the registry', () => {
    expect(Object.keys(links).sort()).toEqual(lessons.map((l) => l.slug).sort());
  });

  for (const meta of lessons) {
    it(`${meta.slug}: every scene's link opens the same state, and every scene sets it up`, async () => {
      const lesson = await meta.load();
      const figures = lesson.figures.map((f) => f.id);
      const scenes = (lesson.scenes ?? []).map((s) => s.id);
      for (const link of links[meta.slug]) {
        const decoded = decodeState(lesson.schema, link, figures, scenes);
        expect(decoded.issues, link).toEqual([]);
        const state = normalizeState(lesson, decoded.state);
        expect(state.issues, link).toEqual([]);
        const scene = /^scene=([^&]+)/.exec(link)?.[1];
        expect(encodeState(lesson.schema, state.state, {}, scene), link).toBe(link);
      }
      // The same links, made now from the defaults and each scene's setup.
      const defaults = normalizeState(lesson, defaultsOf(lesson.schema)).state;
      const now = [encodeState(lesson.schema, defaults)];
      const key = lesson.steps?.key;
      for (const scene of lesson.scenes ?? []) {
        const s = normalizeState(lesson, scene.apply(defaults)).state as Record<string, unknown>;
        const last = key ? lesson.steps!.count({ ...s, [key]: 0 }) : 0;
        for (const k of key ? [0, last] : [0]) {
          const at = key ? normalizeState(lesson, { ...s, [key]: k }).state : s;
          now.push(encodeState(lesson.schema, at, {}, scene.id));
        }
      }
      expect(now).toEqual(links[meta.slug]);
    });
  }
});

describe('a short link that names a scene', () => {
  for (const meta of lessons) {
    it(`${meta.slug}: “scene=<id>” alone opens that scene as its link opens it, and a field it gives wins`, async () => {
      const lesson = await meta.load();
      // The recorded link of each scene at step 0 is the whole state that scene opens with.
      const key = lesson.steps?.key;
      const first = (l: string) =>
        !key || new RegExp(`&${keyOf(lesson.schema, key)}=0(&|$)`).test(l);
      const opening = links[meta.slug].filter((l) => l.startsWith('scene=') && first(l));
      expect(opening.length).toBe(lesson.scenes?.length ?? 0);
      for (const link of opening) {
        const id = /^scene=([^&]+)/.exec(link)![1];
        const opened = loadState(lesson, `scene=${id}`, null);
        expect(opened.issues, id).toEqual([]);
        expect(encodeState(lesson.schema, opened.state, {}, id), id).toBe(link);
      }
      // A field the link gives is kept over the scene's own (here the step).
      const last = lesson.scenes?.at(-1);
      if (!key || !last) return;
      const whole = links[meta.slug].filter((l) => l.startsWith(`scene=${last.id}&`)).at(-1)!;
      const end = Number(new RegExp(`&${keyOf(lesson.schema, key)}=(\\d+)`).exec(whole)![1]);
      const opened = loadState(
        lesson,
        `scene=${last.id}&${keyOf(lesson.schema, key)}=${end}`,
        null,
      );
      expect(encodeState(lesson.schema, opened.state, {}, last.id)).toBe(whole);
    });
  }
});

describe('a link to a step past the last', () => {
  for (const meta of lessons) {
    it(`${meta.slug}: shows the scene's last step, and says so`, async () => {
      const lesson = await meta.load();
      const key = lesson.steps!.key;
      const linkKey = keyOf(lesson.schema, key);
      for (const scene of lesson.scenes ?? []) {
        const loaded = loadState(lesson, `scene=${scene.id}&${linkKey}=500`, null);
        const state = loaded.state as Record<string, unknown>;
        // The last step, counted from the scene's own list of steps at step 0.
        const last = lesson.steps!.count({ ...state, [key]: 0 });
        expect(state[key], scene.id).toBe(last);
        expect(loaded.issues.join(' '), scene.id).toContain(
          `${linkKey}: 500 is past the last step of this construction (${last}), so it shows step ${last}`,
        );
      }
    });
  }
});

describe('a link without its scene', () => {
  for (const meta of lessons) {
    it(`${meta.slug}: opens the scene whose picture it shows, so the caption says the scene it is`, async () => {
      const lesson = await meta.load();
      const ids = (lesson.scenes ?? []).map((s) => s.id);
      // Each recorded scene link with its "scene=" cut off: the scene is the
      // first whose own link is the same state (two scenes may open alike).
      const cut = links[meta.slug]
        .filter((l) => l.startsWith('scene='))
        .map((l) => ({ id: /^scene=([^&]+)/.exec(l)![1], rest: l.replace(/^scene=[^&]+&/, '') }));
      for (const { id, rest } of cut) {
        const first = cut.find((other) => other.rest === rest)!.id;
        const loaded = loadState(lesson, rest, null);
        expect(loaded.issues, rest).toEqual([]);
        expect(ids[loaded.scene], `${id}: ${rest}`).toBe(first);
      }
    });
  }

  it('raster: a link written by hand, x=compare&step=4, is the comparison scene', async () => {
    const lesson = await lessons.find((l) => l.slug === 'raster')!.load();
    const loaded = loadState(lesson, 'x=compare&step=4', null);
    expect(lesson.scenes![loaded.scene].id).toBe('compare');
  });

  it('a link that names one scene and sets another’s state opens the scene of its state', async () => {
    const lesson = await lessons.find((l) => l.slug === 'raster')!.load();
    const loaded = loadState(lesson, 'scene=plot&x=pixels', null);
    expect(lesson.scenes![loaded.scene].id).toBe('pixels');
  });
});
