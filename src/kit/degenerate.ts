/** What is degenerate about a list of points: all on one spot, all on one line, neighbours on one spot. */
export interface Degenerate {
  allSame: boolean;
  /** Three or more points, all on one line (and not all on one spot). */
  collinear: boolean;
  /** Pairs of neighbours i, i + 1 on one spot. */
  repeats: number[];
}

/** What `degenerate` finds: where a construction through these points cannot be drawn or solved. */
export function degenerate(p: readonly (readonly number[])[]): Degenerate {
  let far = 0;
  const dist = (a: readonly number[], b: readonly number[]) => Math.hypot(a[0] - b[0], a[1] - b[1]);
  for (let i = 1; i < p.length; i++) if (dist(p[i], p[0]) > dist(p[far], p[0])) far = i;
  const length = dist(p[far], p[0]);
  const allSame = length === 0;
  const [dx, dy] = [p[far][0] - p[0][0], p[far][1] - p[0][1]];
  const offLine = allSame
    ? 0
    : Math.max(...p.map((q) => Math.abs((q[0] - p[0][0]) * dy - (q[1] - p[0][1]) * dx) / length));
  const repeats: number[] = [];
  for (let i = 0; i + 1 < p.length; i++)
    if (p[i][0] === p[i + 1][0] && p[i][1] === p[i + 1][1]) repeats.push(i);
  return { allSame, collinear: !allSame && p.length > 2 && offLine <= 1e-9 * length, repeats };
}

/** "P1 = P2, P4 = P5": the repeated neighbours named (at most four). */
export function repeatsText(repeats: readonly number[], name = 'P'): string {
  const pairs = repeats.map((i) => `${name}${i} = ${name}${i + 1}`);
  return pairs.length > 4 ? `${pairs.slice(0, 4).join(', ')}, …` : pairs.join(', ');
}
