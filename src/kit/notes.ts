import { h } from '../app/dom';

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
  return h('p', { class: 'notes-aside', role: 'note' }, slipText(doc, written, correct));
}

/** The words of `notesSlip`: "The lecture notes write …", "The practical (TP2) writes …". */
export function slipText(doc: NotesDocument, written: string, correct: string): string {
  const name = documentName(doc);
  const lead = name.charAt(0).toUpperCase() + name.slice(1);
  const verb = doc === 'practical' ? 'writes' : 'write';
  return `${lead} ${verb} ${written}. ${correct}`;
}

/**
 * How the app's symbols read in the notes: one small key per lesson, e.g.
 * `notesKey([['P_{r,i}', 'b_i^{(r)} in the continuation notes'], …])`, rows of
 * (app's symbol in plain Unicode, how the notes write it).
 */
export function notesKey(rows: readonly (readonly [string, string])[]): HTMLElement {
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
