import type { RowSpec } from '../../app/liveTable';
import { smallNumber, superscript } from '../../kit/format';
import { texNumber } from '../../render/formula';
import { derivativeName, smoothName } from './continuityScript';
import type { BSplineModel } from './model';
import { isUniformPart } from './state';

const num = (v: number) => texNumber(v, 4);
/** A point whole on its line (a no-break space): a value may wrap between points, not inside one. */
const point = (p: readonly number[]) => `(${num(p[0])},\u00A0${num(p[1])})`;
const row = (name: string, value: string, className = ''): RowSpec => ({
  cells: [name, value],
  className,
});

/** The numbers a student can check against the figure, for the part shown. */
export function facts(m: BSplineModel): RowSpec[] {
  const s = m.state;
  const n = s.points.length;
  const rows: RowSpec[] = [];
  const uniform = isUniformPart(s.part);
  rows.push(row(uniform ? 'parameter s' : 'parameter u', num(m.u)));
  rows.push(row(uniform ? 'P(s)' : 'P(u)', point(m.point)));
  if (!uniform) {
    rows.push(row('curve start P(u(p))', point(m.start)));
    rows.push(row('P0', point(s.points[0])));
    rows.push(row('curve end P(u(m+1))', point(m.end)));
    rows.push(row(`P${n - 1}`, point(s.points[n - 1])));
    for (const join of m.joins) {
      const through =
        join.through === null
          ? ''
          : `, through P${join.through}: distance ${smallNumber(Math.hypot(join.at[0] - s.points[join.through][0], join.at[1] - s.points[join.through][1]))}`;
      rows.push(
        row(
          `knot ${texNumber(join.u, 3)} ×${join.multiplicity}`,
          `${join.continuity < 0 ? 'jump' : `C${superscript(join.continuity)}`}${through}`,
          join.continuity <= 0 ? 'current' : '',
        ),
      );
    }
  } else if (s.part !== 'closed') {
    rows.push(row('curve start', point(m.start)));
    rows.push(row('curve end', point(m.end)));
  }
  const sum = m.basis.reduce((a, b) => a + b, 0);
  rows.push(row('Σ basis at the cursor', num(sum)));
  rows.push(...sceneFacts(m));
  return rows;
}

/** The numbers only one scene has. */
function sceneFacts(m: BSplineModel): RowSpec[] {
  switch (m.kind) {
    case 'local': {
      const changed = m.localControl.changed.filter(Boolean).length;
      return [row('segments changed', `${changed} of ${m.segments.length}`)];
    }
    case 'properties':
      return [
        row('line × polygon', String(m.properties.crossings.polygon)),
        row('line × curve', String(m.properties.crossings.curve)),
        row('affine: largest gap', smallNumber(m.properties.deviation)),
      ];
    case 'circle':
      return [
        row('circle: largest |‖P − c‖ − r|', smallNumber(m.circle.deviation)),
        row('all weights 1: largest gap', num(m.circle.plainDeviation)),
      ];
    case 'projective':
      return m.projective.error
        ? []
        : [
            row('H(P) vs NURBS of H(Pi), w′', smallNumber(m.projective.deviation)),
            row('H(P) vs old weights', num(m.projective.plainDeviation)),
          ];
    case 'meanings':
      return m.knotPoints.map((k) =>
        row(
          `P(u${k.index}) at the knot u = ${texNumber(k.u, 3)}`,
          `${point(k.at)}${k.on === null ? '' : ` = P${k.on}`}`,
        ),
      );
    case 'continuity': {
      const check = m.watched;
      const at = texNumber(check.u, 3);
      return [
        ...check.left.map((left, r) =>
          row(
            `${derivativeName(r)} left | right of u = ${at}`,
            `${point(left)} ${check.agree[r] ? '=' : '≠'} ${point(check.right[r])}`,
          ),
        ),
        row(`continuity at u = ${at}`, smoothName(check.smooth), 'current'),
      ];
    }
    default:
      return [];
  }
}
