/**
 * What the app tells the reader besides the page itself: notices (a few at a
 * time along the top, each dismissable) and the announcer, a live region a
 * screen reader speaks and nobody sees.
 */
import { h } from './dom';

/** The notices along the top of the page. */
export interface Notices {
  element: HTMLElement;
  /** Shows a notice; beyond four, the oldest go. */
  notice(message: string): void;
  /** Takes every notice away (another page opens). */
  clear(): void;
}

export function noticeList(): Notices {
  const element = h('div', { class: 'notices', role: 'status', 'aria-live': 'polite' });
  return {
    element,
    notice: (message) => {
      const close = h(
        'button',
        { type: 'button', class: 'notice-close', 'aria-label': 'Dismiss notice' },
        '×',
      );
      const item = h('div', { class: 'notice' }, h('span', {}, message), close);
      close.addEventListener('click', () => item.remove());
      element.append(item);
      while (element.childElementCount > 4) element.firstElementChild?.remove();
    },
    clear: () => element.replaceChildren(),
  };
}

/** The live region a lesson page announces through. */
export interface Announcer {
  element: HTMLElement;
  announce(message: string): void;
}

export function liveAnnouncer(): Announcer {
  const element = h('div', {
    class: 'visually-hidden',
    'aria-live': 'polite',
    'data-announcer': '',
  });
  return {
    element,
    announce: (message) => {
      // Written even when the words are the same: a live region then says them again.
      // eslint-disable-next-line no-restricted-syntax
      element.textContent = message;
    },
  };
}
