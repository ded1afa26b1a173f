import { DEFAULT_LETTER, type Letter, parseLetter } from '../render/notation';
import { makeTheme, type Theme } from '../render/theme';

/** Display settings that belong to the device, not to a lesson's link. */
export interface Settings {
  projector: boolean;
  dark: boolean;
  /** The curve parameter's letter: μ (the lecture notes), u (the slides) or t (the practical). */
  letter: Letter;
}

const KEY = 'spline-lab:settings';

export function loadSettings(): Settings {
  const prefersDark =
    typeof matchMedia === 'function' && matchMedia('(prefers-color-scheme: dark)').matches;
  const fallback: Settings = { projector: false, dark: prefersDark, letter: DEFAULT_LETTER };
  try {
    const raw = localStorage.getItem(KEY);
    if (!raw) return fallback;
    const parsed: unknown = JSON.parse(raw);
    if (typeof parsed !== 'object' || parsed === null) return fallback;
    const record = parsed as Record<string, unknown>;
    return {
      projector: record.projector === true,
      dark: typeof record.dark === 'boolean' ? record.dark : prefersDark,
      letter: (typeof record.letter === 'string' && parseLetter(record.letter)) || DEFAULT_LETTER,
    };
  } catch {
    return fallback;
  }
}

export function saveSettings(settings: Settings): void {
  try {
    localStorage.setItem(KEY, JSON.stringify(settings));
  } catch {
    // Private mode or full storage: the setting just lasts this visit.
  }
}

/** Whether the page is in presenter view now (the hook applySettings sets). */
export const presenting = (): boolean => document.documentElement.classList.contains('projector');

/** Sets the page's CSS hooks and returns the canvas theme. */
export function applySettings(settings: Settings): Theme {
  const root = document.documentElement;
  root.dataset.theme = settings.dark ? 'dark' : 'light';
  root.classList.toggle('projector', settings.projector);
  return makeTheme(settings.dark, settings.projector);
}

export function prefersReducedMotion(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
}
