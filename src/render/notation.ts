/**
 * The curve parameter's letter, chosen by the reader: μ as in the lecture
 * notes, u as in the lecture slides, t as in the practical and the
 * continuation notes. A lesson writes its text with its own letter (t or μ);
 * everything it shows (captions, formulas, panel text, figure labels, link
 * names) goes through here on its way to the screen and comes out in the
 * reader's letter. Only the lesson's own letter changes: other symbols (T for
 * the tangent, s for arc length, u and v of a surface) are left alone, and so
 * is anything quoted from the notes (the symbol keys and the notes' asides
 * say how the notes write it).
 */

export type Letter = 'mu' | 'u' | 't';

export const LETTERS: readonly Letter[] = ['mu', 'u', 't'];

/** The letter used until the reader chooses one: t, as in the practical and the continuation notes. */
export const DEFAULT_LETTER: Letter = 't';

/** The key that carries the letter in a link (`par=mu`), owned by the shell like the scene. */
export const LETTER_KEY = 'par';

interface LetterForms {
  /** As plain text: "μ". */
  plain: string;
  /** As TeX, safe to follow by any character: "{\mu}". */
  tex: string;
  /** Where the course writes it, for the setting's menu. */
  source: string;
}

export const LETTER_FORMS: Readonly<Record<Letter, LetterForms>> = {
  mu: { plain: 'μ', tex: '{\\mu}', source: 'the lecture notes' },
  u: { plain: 'u', tex: 'u', source: 'the slides' },
  t: { plain: 't', tex: 't', source: 'the practical and the continuation notes' },
};

/** A letter's name in a link, or null when it is none of them ("mu", "u", "t"; "μ" too). */
export function parseLetter(raw: string): Letter | null {
  if (raw === 'μ') return 'mu';
  return (LETTERS as readonly string[]).includes(raw) ? (raw as Letter) : null;
}

// A plain-text letter stands alone: not inside a word ("don’t", "at"), not a
// command's name. Subscripts, primes and brackets may touch it: "t₁", "tₖ", "P(t)".
const BEFORE = String.raw`(?<![\p{L}\p{N}'’\\_])`;
const AFTER = String.raw`(?![\p{L}'’](?<![\u2090-\u209C\u1D62-\u1D6A\u2C7C]))`;
const PLAIN: Readonly<Record<Letter, RegExp>> = {
  mu: /μ/gu,
  u: new RegExp(`${BEFORE}u${AFTER}`, 'gu'),
  t: new RegExp(`${BEFORE}t${AFTER}`, 'gu'),
};

/** Plain text with the letter `from` written as `to`. */
export function renamePlain(text: string, from: Letter, to: Letter): string {
  if (from === to) return text;
  const pattern = PLAIN[from];
  pattern.lastIndex = 0;
  return pattern.test(text) ? text.replace(PLAIN[from], LETTER_FORMS[to].plain) : text;
}

/** Commands whose braced argument is words: the letter in it is renamed as in plain text. */
const WORDS = new Set(['text', 'textrm', 'textit', 'textbf', 'mbox', 'operatorname', 'mathrm']);
/** Commands whose braced argument is a name, not maths: left exactly as it is. */
const NAMES = new Set(['begin', 'end', 'htmlData', 'hspace', 'color', 'textcolor', 'htmlClass']);

/** The end (exclusive) of a braced group that starts at `open` (a "{"), or -1. */
function groupEnd(tex: string, open: number): number {
  let depth = 0;
  for (let i = open; i < tex.length; i++) {
    const c = tex[i];
    if (c === '\\') i++;
    else if (c === '{') depth++;
    else if (c === '}' && --depth === 0) return i + 1;
  }
  return -1;
}

/**
 * TeX with the letter `from` written as `to`. In maths every letter is a
 * symbol of its own, so a lone t (or \mu, or μ) is the parameter; a command's
 * name (\frac, \text, \left) is not, words in \text{…} are renamed as plain
 * text, and names in \begin{…} or \htmlData{…} are kept.
 */
export function renameTex(tex: string, from: Letter, to: Letter): string {
  if (from === to) return tex;
  const target = LETTER_FORMS[to].tex;
  let out = '';
  let i = 0;
  while (i < tex.length) {
    const c = tex[i];
    if (c === '\\') {
      const name = /^\\([a-zA-Z]+)/.exec(tex.slice(i));
      if (!name) {
        out += tex.slice(i, i + 2);
        i += 2;
        continue;
      }
      const command = name[1];
      i += name[0].length;
      if (command === 'mu' && from === 'mu') {
        out += target;
        continue;
      }
      out += `\\${command}`;
      if ((WORDS.has(command) || NAMES.has(command)) && tex[i] === '{') {
        const end = groupEnd(tex, i);
        if (end < 0) continue;
        const group = tex.slice(i, end);
        out += WORDS.has(command) ? renamePlain(group, from, to) : group;
        i = end;
      }
      continue;
    }
    if ((from === 'mu' && c === 'μ') || (from !== 'mu' && c === from)) out += target;
    else out += c;
    i++;
  }
  return out;
}

/** What the page shows now: the open lesson's own letter and the reader's. */
let lessonLetter: Letter | null = null;
let readerLetter: Letter = DEFAULT_LETTER;

/**
 * Sets the letters for what is drawn and typeset from now on: the lesson's own
 * (null for a lesson whose letters are all its own, as the surface's u and v)
 * and the reader's choice.
 */
export function setNotation(lesson: Letter | null, reader: Letter): void {
  lessonLetter = lesson;
  readerLetter = reader;
}

/** The open lesson's own letter, or null when its letters are all its own. */
export function shownLetter(): Letter | null {
  return lessonLetter;
}

/** The reader's letter. */
export function chosenLetter(): Letter {
  return readerLetter;
}

/** Plain text as the reader reads it. */
export function say(text: string): string {
  return lessonLetter === null ? text : renamePlain(text, lessonLetter, readerLetter);
}

/**
 * A negative number written with a hyphen (−0.65 as `toFixed` and `String`
 * write it, "-0.65") with a true minus sign instead, as the figures and
 * formulas write it (#19). Only a hyphen that starts a number: not one after
 * a letter, a digit or a closing bracket (P0-P1, 2-4, x-1 are left alone).
 */
export function minusSigns(text: string): string {
  return text.includes('-') ? text.replace(/(?<![\p{L}\p{N}_)\]])-(?=\.?\d)/gu, '\u2212') : text;
}

/** TeX as the reader reads it. */
export function sayTex(tex: string): string {
  return lessonLetter === null ? tex : renameTex(tex, lessonLetter, readerLetter);
}
