import { encode } from 'uqr';

const SVG = 'http://www.w3.org/2000/svg';

/**
 * The QR code of a link as an SVG element of `size` mm, built from the
 * library's module matrix as one path (no markup is parsed).
 */
export function qrCode(link: string, size: number): SVGSVGElement {
  const { data } = encode(link, { ecc: 'M', border: 1 });
  const n = data.length;
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', `0 0 ${n} ${n}`);
  svg.setAttribute('width', `${size}mm`);
  svg.setAttribute('height', `${size}mm`);
  svg.setAttribute('shape-rendering', 'crispEdges');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', 'QR code of the link to this lesson');
  const background = document.createElementNS(SVG, 'rect');
  background.setAttribute('width', String(n));
  background.setAttribute('height', String(n));
  background.setAttribute('fill', '#ffffff');
  const path = document.createElementNS(SVG, 'path');
  const d: string[] = [];
  data.forEach((row, y) =>
    row.forEach((dark, x) => {
      if (dark) d.push(`M${x} ${y}h1v1h-1z`);
    }),
  );
  path.setAttribute('d', d.join(''));
  path.setAttribute('fill', '#000000');
  svg.append(background, path);
  return svg;
}
