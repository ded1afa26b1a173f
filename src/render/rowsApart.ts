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
  let i = 0;
  while (i < tex.length) {
    const rest = tex.slice(i);
    const begin = /^\\begin\{([a-zA-Z*]+)\}/.exec(rest);
    const end = /^\\end\{([a-zA-Z*]+)\}/.exec(rest);
    if (begin) {
      if (!inBlock && depth === 0 && begin[1] === 'aligned') {
        inBlock = true;
        found = true;
        // A space, so a command before it keeps its name (\quad\begin… is not \quadM).
        out += ' ';
        inner = 0;
        column = 0;
      } else {
        out += begin[0];
        nest(1);
      }
      i += begin[0].length;
      continue;
    }
    if (end) {
      if (inBlock && inner === 0 && end[1] === 'aligned') {
        inBlock = false;
        out += ' ';
      } else {
        out += end[0];
        nest(-1);
      }
      i += end[0].length;
      continue;
    }
    const command = /^\\(?:[a-zA-Z]+|.)/.exec(rest);
    if (command) {
      const name = command[0];
      if (name === '\\\\' && inBlock && inner === 0) column = 0;
      if (name === '\\left') nest(1);
      if (name === '\\right') nest(-1);
      out += name;
      i += name.length;
      continue;
    }
    const char = tex[i];
    if (char === '{') nest(1);
    if (char === '}') nest(-1);
    if (char === '&' && inBlock && inner === 0) {
      column++;
      // The odd & of a row marks where it aligns; the even one parts two equations.
      out += column % 2 === 0 ? '\\quad ' : ' ';
    } else out += char;
    i++;
  }
  return found ? out : null;
}
