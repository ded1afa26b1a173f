import { h } from '../app/dom';
import { LETTERS, LETTER_FORMS, chosenLetter, shownLetter } from '../render/notation';

// How a lesson speaks about the course notes (../shared/notes): where the
// notes write something another way, or slip, the lesson says so beside the
// correct statement, kindly, in one place and one style.

/** The course's documents, as a student holding them names them. */
export type NotesDocument = 'lecture' | 'continuation' | 'slides' | 'spline slides' | 'practical';

const DOCUMENT_NAMES: Record<NotesDocument, string> = {
  lecture: 'the lecture notes',
  continuation: 'the continuation notes',
  slides: 'the lecture slides',
  'spline slides': 'the “Splines” slides',
  practical: 'the practical (TP2)',
};

/** "the lecture notes", "the practical (TP2)": for a sentence that cites one. */
export function documentName(doc: NotesDocument): string {
  return DOCUMENT_NAMES[doc];
}

/**
 * A slip in the notes, said kindly beside the correct statement:
 * `notesSlip('practical', 'the first derivative as d²/dt²', 'The first derivative is d/dt.')`
 * reads "The practical (TP2) writes the first derivative as d²/dt². The first derivative is d/dt."
 */
export function notesSlip(doc: NotesDocument, written: string, correct: string): HTMLElement {
  // What the notes write is quoted as they write it; the correction is in the reader's letter.
  const quoted = slipText(doc, written, '').trimEnd();
  return h(
    'p',
    { class: 'notes-aside', role: 'note' },
    h('span', { 'data-notation': 'own' }, quoted),
    ` ${correct}`,
  );
}

/** The words of `notesSlip`: "The lecture notes write …", "The practical (TP2) writes …". */
export function slipText(doc: NotesDocument, written: string, correct: string): string {
  const name = documentName(doc);
  const lead = name.charAt(0).toUpperCase() + name.slice(1);
  const verb = doc === 'practical' ? 'writes' : 'write';
  return `${lead} ${verb} ${written}. ${correct}`;
}

/**
 * Words or a formula quoted as the notes write them, letters and all: the
 * reader's choice of letter for the parameter does not touch them
 * (`notesQuote('x(t) = at³ + bt² + ct + d')`, or an element to keep whole).
 */
export function notesQuote(quoted: string | HTMLElement): HTMLElement {
  if (typeof quoted !== 'string') {
    quoted.dataset.notation = 'own';
    return quoted;
  }
  return h('span', { 'data-notation': 'own' }, quoted);
}

/**
 * How the app's symbols read in the notes: one small key per lesson, e.g.
 * `notesKey([['P_{r,i}', 'b_i^{(r)} in the continuation notes'], …])`, rows of
 * (app's symbol in plain Unicode, how the notes write it).
 */
export function notesKey(rows: readonly (readonly [string, string])[]): HTMLElement {
  // The curve parameter's row is the kit's: the reader's letter, and how each document writes it.
  const parameter = parameterRow();
  if (parameter) rows = [parameter, ...rows];
  return h(
    'details',
    { class: 'notes-key' },
    h('summary', {}, 'Symbols here and in the notes'),
    h(
      'dl',
      {},
      rows.flatMap(([here, there]) => [h('dt', {}, here), h('dd', {}, there)]),
    ),
  );
}

/**
 * The key's row for the curve parameter, in a lesson that writes one: the
 * letter the reader chose, and the letter of each of the notes.
 */
export function parameterRow(): readonly [string, string] | null {
  if (shownLetter() === null) return null;
  const here = LETTER_FORMS[chosenLetter()].plain;
  return [
    `${here}, the curve’s parameter`,
    `${LETTERS.map((l) => `${LETTER_FORMS[l].plain} in ${LETTER_FORMS[l].source}`).join(', ')}; the letter is chosen at the top of the page`,
  ];
}
