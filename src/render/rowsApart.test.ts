import katex from 'katex';
import { describe, expect, it } from 'vitest';
import { rowsApart } from './rowsApart';

/** The lines KaTeX sets a formula on: its top-level pieces, cut at each line break. */
function linesOf(tex: string): number {
  const html = katex.renderToString(tex, { displayMode: true, throwOnError: true, strict: false });
  return (html.match(/class="mspace newline"/g) ?? []).length + 1;
}

/** Spaces as TeX reads them in math: any run is one, at the ends none. */
const apart = (tex: string) => rowsApart(tex)?.replace(/\s+/g, ' ').trim() ?? null;

describe('rowsApart', () => {
  it('writes an aligned block’s rows one under another, without their = column', () => {
    expect(apart('\\begin{aligned}a &= b + c\\\\ d &= e\\end{aligned}')).toBe(
      'a = b + c\\\\ d = e',
    );
  });

  it('parts two equations of a row by a quad, where an even & stood', () => {
    // bezier-properties' Hermite data: two equations a row.
    expect(
      apart("\\begin{aligned}x_0 &= P_0, & x_0' &= 3(P_1 - P_0)\\\\ x_1 &= P_3\\end{aligned}"),
    ).toBe("x_0 = P_0, \\quad x_0' = 3(P_1 - P_0)\\\\ x_1 = P_3");
  });

  it('keeps what comes before and after the block, and what is nested in it', () => {
    const tex =
      'u = 0.5:\\quad\\begin{aligned}M &= \\begin{pmatrix}1 & 0\\\\ 0 & 1\\end{pmatrix}\\\\ N &= {a & b}\\end{aligned} = x';
    expect(apart(tex)).toBe(
      'u = 0.5:\\quad M = \\begin{pmatrix}1 & 0\\\\ 0 & 1\\end{pmatrix}\\\\ N = {a & b} = x',
    );
  });

  it('leaves a block inside braces, \\left … \\right or another environment alone', () => {
    expect(apart('x = {\\begin{aligned}a &= b\\end{aligned}}')).toBeNull();
    expect(apart('\\left(\\begin{aligned}a &= b\\end{aligned}\\right)')).toBeNull();
    expect(apart('\\begin{cases}\\begin{aligned}a &= b\\end{aligned}\\end{cases}')).toBeNull();
    expect(apart('a = b + c')).toBeNull();
  });

  it('copies an escaped & and a command’s argument as they are', () => {
    expect(apart('\\begin{aligned}a &= \\text{x & y}\\ \\&\\end{aligned}')).toBe(
      'a = \\text{x & y}\\ \\&',
    );
  });

  it('gives TeX that KaTeX sets on as many lines as the block had rows', () => {
    const rows = [
      '\\begin{aligned}P(0) &= a_0 = P_0\\\\ P(0.5) &= a_2\\cdot 0.5^2 + a_1\\cdot 0.5 + a_0\\\\ P(1) &= a_2 + a_1 + a_0\\end{aligned}',
      '\\begin{aligned}P(\\mu) &= U\\,M\\,\\mathbf{P},\\qquad U = \\begin{pmatrix}1 & \\mu\\end{pmatrix},\\\\ M &= \\begin{pmatrix}1 & 0\\\\ -1 & 1\\end{pmatrix}\\end{aligned}',
    ];
    expect(rows.map((tex) => linesOf(rowsApart(tex)!))).toEqual([3, 2]);
  });
});
