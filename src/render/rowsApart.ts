/** A formula's tokens: an environment's start or end (its name caught), a command, or one character. */
const TOKENS = /\\begin\{([a-zA-Z*]+)\}|\\end\{([a-zA-Z*]+)\}|\\(?:[a-zA-Z]+|[\s\S])?|[^\\]/g;

/**
 * A formula of aligned rows (`\begin{aligned} a &= b \\ c &= d \end{aligned}`)
 * written as the same rows one under another, each free to break after an
 * = or a + as running text does. An aligned block is one piece: the fit can
 * shrink it but never break it, so where it is too wide for its box even at
 * 12 px (a derivation's three rows in a laptop's 404 px panel ran 473 px) it
 * scrolled, its ends cut off. Apart, its rows lose their common = column
 * and keep everything else: each row's alignment point (the odd `&`)
 * goes (a space stays), the gap between a row's equations (the even `&`) becomes a quad,
 * and a row's `\\` becomes a line break of the whole formula.
 *
 * Only an aligned block at the formula's top level is taken apart (not one
 * inside braces, `\left … \right` or another environment, where a line
 * break is not allowed); anything nested in it is copied as it is. Null when
 * the formula has no such block.
 */
export function rowsApart(tex: string): string | null {
  // Most formulas have none: no scan (the fit asks of every formula too wide to fit).
  if (!tex.includes('\\begin{aligned}')) return null;
  let out = '';
  let found = false;
  // Depth in braces, \left … \right and environments, outside the block being taken apart.
  let depth = 0;
  // Inside a top-level aligned block: depth within it, and the row's count of &.
  let inBlock = false;
  let inner = 0;
  let column = 0;
  // Into (1) or out of (-1) a group: the block's own depth inside it, else the formula's.
  const nest = (step: 1 | -1): void => {
    if (inBlock) inner += step;
    else depth += step;
  };
  // One pass over its tokens: \begin{…}, \end{…}, a command, or one character.
  for (const [token, begin, end] of tex.matchAll(TOKENS)) {
    if (begin !== undefined) {
      if (!inBlock && depth === 0 && begin === 'aligned') {
        inBlock = true;
        found = true;
        // A space, so a command before it keeps its name (\quad\begin… is not \quadM).
        out += ' ';
        inner = 0;
        column = 0;
      } else {
        out += token;
        nest(1);
      }
    } else if (end !== undefined) {
      if (inBlock && inner === 0 && end === 'aligned') {
        inBlock = false;
        out += ' ';
      } else {
        out += token;
        nest(-1);
      }
    } else if (token.length > 1 || token === '\\') {
      if (token === '\\\\' && inBlock && inner === 0) column = 0;
      if (token === '\\left') nest(1);
      if (token === '\\right') nest(-1);
      out += token;
    } else {
      if (token === '{') nest(1);
      if (token === '}') nest(-1);
      if (token === '&' && inBlock && inner === 0) {
        column++;
        // The odd & of a row marks where it aligns; the even one parts two equations.
        out += column % 2 === 0 ? '\\quad ' : ' ';
      } else out += token;
    }
  }
  return found ? out : null;
}
