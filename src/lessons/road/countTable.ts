import type { RowSpec } from '../../app/liveTable';
import { SHAPE } from './methods';
import type { RoadModel } from './model';
import type { RoadMethod } from './state';

/** What each method leaves to choose once every condition is counted. */
const FREE: Record<RoadMethod, string> = {
  roman: 'nothing left to choose',
  quadratic: 'the gradient at P0',
  hermite: 'a gradient at every village (from the parabolas)',
  natural: 'P″ = 0 at both ends',
  clamped: 'the gradients at both ends',
  ring: 'nothing: a ring has no ends',
};

/** The counting argument: unknown coefficients against the conditions the villages impose. */
export function countRows(model: RoadModel): RowSpec[] {
  const c = model.count;
  if (!c) return [{ cells: ['A ring road needs at least three villages.'] }];
  const shape = SHAPE[model.state.road];
  const k = shape.degree + 1;
  const perJoin = 2 + shape.continuity;
  const joins = shape.closed ? 'villages' : 'inner villages';
  const rows: [string, string][] = [
    [`Segments${shape.closed ? ' (m + 1, closed)' : ' m'}`, `${c.segments}`],
    [`Unknowns: ${k} coefficients per segment`, `${k}·${c.segments} = ${c.unknowns}`],
    [
      `${perJoin} conditions at each of the ${c.inner / perJoin || 0} ${joins} (position twice${shape.continuity >= 1 ? ', gradient' : ''}${shape.continuity >= 2 ? ', 2nd derivative' : ''})`,
      `${c.inner}`,
    ],
    ['Positions at the two ends', `${c.ends}`],
    [`Left to choose: ${FREE[model.state.road]}`, `${c.free}`],
  ];
  return rows.map((cells) => ({ cells }));
}
