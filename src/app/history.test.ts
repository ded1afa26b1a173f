import { describe, expect, it } from 'vitest';
import { History } from './history';

describe('History (undo/redo)', () => {
  it('undoes and redoes single changes', () => {
    const h = new History(0);
    h.push(1);
    h.push(2);
    expect(h.state).toBe(2);
    expect(h.undo()).toBe(1);
    expect(h.undo()).toBe(0);
    expect(h.canUndo).toBe(false);
    expect(h.undo()).toBe(0);
    expect(h.redo()).toBe(1);
    expect(h.redo()).toBe(2);
    expect(h.canRedo).toBe(false);
  });

  it('a new change after undo drops the redo branch', () => {
    const h = new History('a');
    h.push('b');
    h.undo();
    h.push('c');
    expect(h.canRedo).toBe(false);
    expect(h.undo()).toBe('a');
  });

  it('merges one drag into one undo step', () => {
    const h = new History(0);
    for (let i = 1; i <= 50; i++) h.push(i, { coalesce: 'drag:1', now: i });
    h.push(100, { coalesce: 'drag:2', now: 60 });
    expect(h.undo()).toBe(50);
    expect(h.undo()).toBe(0);
  });

  it('merges key presses only within the time window', () => {
    const h = new History(0);
    h.push(1, { coalesce: 'key:p1', windowMs: 1000, now: 0 });
    h.push(2, { coalesce: 'key:p1', windowMs: 1000, now: 500 });
    h.push(3, { coalesce: 'key:p1', windowMs: 1000, now: 5000 });
    expect(h.undo()).toBe(2);
    expect(h.undo()).toBe(0);
  });

  it('replace changes the state without an undo step; the limit drops the oldest', () => {
    const h = new History(0, 3);
    h.replace(9);
    expect(h.canUndo).toBe(false);
    for (let i = 1; i <= 5; i++) h.push(i);
    expect([h.undo(), h.undo(), h.undo(), h.undo()]).toEqual([4, 3, 2, 2]);
  });
});
