/** `#/slug?query` → its parts. The gallery is `#/` (or no hash at all). */
export interface Route {
  slug: string | null;
  query: string;
}

export function parseHash(hash: string): Route {
  const body = hash.startsWith('#') ? hash.slice(1) : hash;
  const path = body.startsWith('/') ? body.slice(1) : body;
  const q = path.indexOf('?');
  const slug = q < 0 ? path : path.slice(0, q);
  const query = q < 0 ? '' : path.slice(q + 1);
  return { slug: slug === '' ? null : slug, query };
}
