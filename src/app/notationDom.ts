import { say } from '../render/notation';

/**
 * The page's words in the reader's letter. Lessons build their panels,
 * captions, sliders and practice cards with their own letter; whatever text
 * or accessible name appears under `root` is rewritten as it appears, so no
 * lesson has to remember to. Formulas are typeset in the reader's letter
 * already (render/formula), and quotations of the notes (the symbol key, the
 * notes' asides) and what the reader types are left as they are.
 */
const KEPT = '.katex, .notes-key dd, textarea, [data-notation="own"]';
const NAMES = ['aria-label', 'title', 'placeholder', 'aria-valuetext'];

/**
 * What `text`, written into `node`, reads as once this module has seen it:
 * in the reader's letter, unless the node keeps the lesson's own. A panel
 * compares with this before it writes, or a text in another letter would be
 * written, then said again, on every frame.
 */
export function shownText(node: Node, text: string): string {
  const element = node instanceof Element ? node : node.parentElement;
  if (!element || element.closest(KEPT)) return text;
  return say(text);
}

/** An attribute's value as it reads once this module has seen it (see `shownText`). */
export function shownAttribute(element: Element, name: string, value: string): string {
  return NAMES.includes(name) ? shownText(element, value) : value;
}

function sayNode(node: Node): void {
  if (node.nodeType === Node.TEXT_NODE) {
    const parent = node.parentElement;
    if (!parent || parent.closest(KEPT)) return;
    const text = node.nodeValue ?? '';
    const said = say(text);
    if (said !== text) node.nodeValue = said;
    return;
  }
  if (!(node instanceof Element) || node.closest(KEPT)) return;
  sayNames(node);
  const walker = document.createTreeWalker(node, NodeFilter.SHOW_TEXT | NodeFilter.SHOW_ELEMENT, {
    acceptNode: (n) =>
      n instanceof Element && n.matches(KEPT) ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT,
  });
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    if (n instanceof Element) sayNames(n);
    else {
      const text = n.nodeValue ?? '';
      const said = say(text);
      if (said !== text) n.nodeValue = said;
    }
  }
}

function sayNames(element: Element): void {
  for (const name of NAMES) {
    const value = element.getAttribute(name);
    if (value === null) continue;
    const said = say(value);
    if (said !== value) element.setAttribute(name, said);
  }
}

/** Keeps what appears under `root` in the reader's letter; returns how to stop. */
export function watchNotation(root: Element): () => void {
  sayNode(root);
  const observer = new MutationObserver((records) => {
    for (const record of records) {
      if (record.type === 'childList') record.addedNodes.forEach(sayNode);
      else if (record.type === 'characterData') sayNode(record.target);
      else if (record.target instanceof Element && !record.target.closest(KEPT))
        sayNames(record.target);
    }
  });
  observer.observe(root, {
    subtree: true,
    childList: true,
    characterData: true,
    attributes: true,
    attributeFilter: NAMES,
  });
  return () => observer.disconnect();
}
