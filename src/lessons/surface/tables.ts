import type { HandoutTable } from '../../app/lesson';
import { fixed } from '../../kit/format';
import type { SurfaceModel } from './model';

const triple = (p: readonly number[]) => p.map((v) => fixed(v, 2)).join(', ');

/** The handout's 4 × 4 control net Pₘ,ₙ: m down, n across, as the panel's table. */
export function netTables({ state }: SurfaceModel): HandoutTable[] {
  return [
    {
      title: 'The control net Pₘ,ₙ = (x, y, z): m down, n across',
      columns: ['', ...[0, 1, 2, 3].map((n) => `n = ${n}`)],
      rows: state.net.map((row, m) => [`m = ${m}`, ...row.map(triple)]),
    },
  ];
}
