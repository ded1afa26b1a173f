import { describe, expect, it } from 'vitest';
import { PROGRESS_KEY, lessonProgress, readProgress, recordTotal, recordTry } from './progress';

/** A Storage kept in memory, as a browser's localStorage behaves. */
function memoryStorage(): Storage {
  const data = new Map<string, string>();
  return {
    get length() {
      return data.size;
    },
    clear: () => data.clear(),
    getItem: (key) => data.get(key) ?? null,
    key: (i) => [...data.keys()][i] ?? null,
    removeItem: (key) => void data.delete(key),
    setItem: (key, value) => void data.set(key, String(value)),
  };
}

describe('practice progress on the device', () => {
  it('counts every check and marks an exercise done on its first right answer', () => {
    const storage = memoryStorage();
    expect(recordTry('blending', 'weight', false, storage)).toEqual({ done: false, tries: 1 });
    expect(recordTry('blending', 'weight', true, storage)).toEqual({ done: true, tries: 2 });
    // Done stays done after a later wrong answer.
    expect(recordTry('blending', 'weight', false, storage)).toEqual({ done: true, tries: 3 });
    recordTry('blending', 'where', false, storage);
    recordTry('road', 'weight', true, storage);
    recordTotal('blending', 3, storage);
    const progress = readProgress(storage);
    expect(lessonProgress('blending', progress)).toEqual({ done: 1, total: 3 });
    expect(lessonProgress('road', progress)).toEqual({ done: 1, total: 0 });
    expect(lessonProgress('surface', progress)).toEqual({ done: 0, total: 0 });
  });
  it('starts again from damaged storage instead of failing', () => {
    const storage = memoryStorage();
    storage.setItem(PROGRESS_KEY, '{not json');
    expect(readProgress(storage)).toEqual({ exercises: {}, totals: {} });
    storage.setItem(PROGRESS_KEY, JSON.stringify({ exercises: { 'a/b': { done: 'yes' } } }));
    expect(readProgress(storage).exercises).toEqual({});
    expect(recordTry('a', 'b', true, storage)).toEqual({ done: true, tries: 1 });
  });
  it('works without storage (private mode): nothing is kept, nothing throws', () => {
    expect(recordTry('a', 'b', true, null)).toEqual({ done: true, tries: 1 });
    expect(readProgress(null)).toEqual({ exercises: {}, totals: {} });
  });
});
