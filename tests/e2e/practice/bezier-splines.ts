import type { PracticeCase } from './types';

export default [
  {
    // p₀ (0, 1), p₁ (2, 0), p₂ (4, 1), p₃ (6, 2), p₄ (8, 2), b₀ = (0.5, 1); C¹ at each pᵢ: bᵢ = 2pᵢ − bᵢ₋₁.
    // b₁ = (4 − 0.5, 0 − 1) = (3.5, −1), b₂ = (8 − 3.5, 2 + 1) = (4.5, 3), b₃ = (12 − 4.5, 4 − 3) = (7.5, 1).
    id: 'mirror-control',
    seed: 1,
    prompt: ['p₃ (6, 2)', 'b₀ = (0.5, 1)', 'Where is b₃'],
    answer: { point: [7.5, 1] },
  },
  {
    // c₀ = p₀ = (0, 2), c₃ = p₁ = (2, 3), c₆ = p₂ = (9, 5). Natural ends c₁ = (c₀ + c₂)/2,
    // c₅ = (c₄ + c₆)/2; C¹ c₄ = 2c₃ − c₂; C² c₁ − 2c₂ + 2c₄ − c₅ = 0 gives 6c₂ = c₀ + 6c₃ − c₆
    // = (0 + 12 − 9, 2 + 18 − 5) = (3, 15): c₂ = (0.5, 2.5).
    // Wrong: c₄ = 2c₃ − c₂ = (3.5, 3.5), the point after the joint.
    id: 'c2-system',
    seed: 1,
    prompt: ['p₀ (0, 2), p₁ (2, 3) and p₂ (9, 5)', 'Where is c₂'],
    answer: { numbers: [0.5, 2.5], wrong: [3.5, 3.5] },
  },
  {
    // c₁ (1, 2), c₂ (2, 3), c₃ (4, 4). C¹: c₄ = 2c₃ − c₂ = (6, 5).
    // C²: c₁ − 2c₂ + c₃ = c₃ − 2c₄ + c₅, so c₅ = c₁ − 2c₂ + 2c₄ = (1 − 4 + 12, 2 − 6 + 10) = (9, 6).
    id: 'c2-joint',
    seed: 1,
    prompt: ['c₁ (1, 2), c₂ (2, 3), c₃ (4, 4)', 'joint at c₃ is C²'],
    answer: {
      moves: [
        { figure: 'main', handle: 'q4', to: [6, 5] },
        { figure: 'main', handle: 'q5', to: [9, 6] },
      ],
    },
  },
] satisfies PracticeCase[];
