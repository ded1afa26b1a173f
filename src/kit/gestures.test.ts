import { describe, expect, it } from 'vitest';
import { gestures } from './gestures';

describe('instructions with the device in hand', () => {
  it('a finger is never told to double-click, right-click, hover or press keys', () => {
    for (const phrase of Object.values(gestures(true)))
      expect(phrase).not.toMatch(
        /double-click|right-click|hover|Tab|arrow|wheel|Shift|Delete key/i,
      );
  });
  it('a mouse is told its own gestures, with the keyboard beside them', () => {
    const mouse = gestures(false);
    expect(mouse.add).toMatch(/double-click/);
    expect(mouse.remove).toMatch(/right-click/);
    expect(mouse.move).toMatch(/Tab/);
    expect(gestures(true).add).toMatch(/press and hold/);
  });
});
