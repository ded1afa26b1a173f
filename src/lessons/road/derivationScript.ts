import { sub } from '../../kit/subscripts';
import { filled, words } from '../../kit/format';
import { repeat, script, step } from '../../kit/script';
import type { StepAt } from '../../kit/script';
import { type DerivationStep, derivationFormula } from './derivationFormulas';
import type { RoadModel } from './model';
import type { Reveal } from './script';
import type { RoadState } from './state';

// The derivation scene: the natural spline's system worked out at one join,
// as the lecture slides do it, each step with the numbers of the villages on
// the map (for y in the caption; the panel has x as well).

type At = StepAt<RoadState, RoadModel>;

/** The step's formula for y, with its numbers. */
const formulaOf =
  (name: DerivationStep) =>
  ({ state, model }: At): string | null => {
    const work = model.derivation;
    if (!work) return null;
    const parts = derivationFormula(name, work, 1, { pBar: state.pBar, ...model.along });
    return parts && filled(parts);
  };

/** The join the steps work at, P j (inner villages only). */
const joinOf = (model: RoadModel) => model.derivation?.join ?? 1;
/** The steps at a join exist when there is an inner village. */
const atJoin = (state: RoadState) => (state.villages.length >= 3 ? 1 : 0);

/** One step of the derivation, named as its formula. */
const derived = (name: DerivationStep & Reveal, caption: (at: At) => string) =>
  step<RoadState, RoadModel, Reveal>(name, caption, formulaOf(name));
/** A step at the chosen join: none with two villages. */
const joined = (name: DerivationStep & Reveal, caption: (at: At) => string) =>
  repeat<RoadState, RoadModel, Reveal>(name, atJoin, caption, formulaOf(name));

export const derivationScript = script<RoadState, RoadModel, Reveal>(
  derived('villages', ({ state }) => {
    const m = state.villages.length - 1;
    return `The ${m + 1} villages P0 … P${m} and their heights y₀ … y${sub(m)}; x is worked out the same way`;
  }),
  derived(
    'pieces',
    () =>
      'Each segment of road is a cubic of its own in its local parameter p: y = a + b p + c p² + d p³',
  ),
  derived('parameter', ({ state, model }) => {
    const { piece, p } = model.along;
    return `Along segment i the local parameter p = (p̄ − p̄ᵢ)/(p̄ᵢ₊₁ − p̄ᵢ) runs from 0 to 1; here p̄ᵢ = i, so the marker at p̄ = ${state.pBar.toFixed(2)} is at p = ${p.toFixed(2)} of segment ${piece}`;
  }),
  joined('left', ({ model }) => {
    const j = joinOf(model);
    return `Segment ${j - 1}, P${j - 1} to the join P${j}: a, b, c, d from heights y and gradients D at its ends`;
  }),
  joined('right', ({ model }) => {
    const j = joinOf(model);
    return `Segment ${j}, from P${j} to P${j + 1}: its a, b, c, d the same way`;
  }),
  joined('second', ({ model }) => {
    const j = joinOf(model);
    const y2 = model.derivation?.coordinates[1].curvature[j - 1][1] ?? 0;
    return `Differentiate twice: y″ = 2c + 6dp, which at the end of segment ${j - 1} (p = 1) is ${words(y2)}`;
  }),
  joined('equal', ({ model }) => {
    const j = joinOf(model);
    return `C² at P${j}: the same second derivative from both sides, p = 1 on segment ${j - 1} and p = 0 on segment ${j}`;
  }),
  joined('substitute', ({ model }) => {
    const j = joinOf(model);
    return `Write each c and d in y and D: one condition on D${j - 1}, D${j} and D${j + 1}`;
  }),
  joined('row', ({ model }) => {
    const j = joinOf(model);
    return `Collect the D’s: D${j - 1} + 4D${j} + D${j + 1} = 3(y${sub(j + 1)} − y${sub(j - 1)}), the row of P${j} in the system`;
  }),
  derived(
    'start',
    () =>
      'The natural end at P0: y″ = 0 where segment 0 starts, so c₀ = 0 and 2D0 + D1 = 3(y₁ − y₀)',
  ),
  derived('end', ({ state }) => {
    const m = state.villages.length - 1;
    return `The natural end at P${m}: y″ = 0 where segment ${m - 1} ends, so D${m - 1} + 2D${m} = 3(y${sub(m)} − y${sub(m - 1)})`;
  }),
  derived('system', ({ state }) => {
    const m = state.villages.length - 1;
    return `Every row together: the tridiagonal system for D0 … D${m}; its solution is the road on the map`;
  }),
);
