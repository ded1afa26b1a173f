/**
 * The app's keys: every key of the keymap, taken in the capture phase so a
 * clicker's PageDown never also moves a focused slider or ticks a box, and
 * sent to the open lesson page or to the app's own display actions.
 */
import { bindingFor, restoresBlank } from './keymap';
import type { KeyTarget, PageKeys } from './keyTarget';

/** What the app itself does (the rest is the open page's). */
export interface AppKeys {
  presenter(): void;
  dark(): void;
  fullscreen(): void;
  help(): void;
  gallery(): void;
  /** The help dialog is open: it has the keys. */
  helpOpen(): boolean;
}

/** Listens for keys on `window` for as long as the app runs. */
export function listenForKeys(page: () => { readonly keys: PageKeys } | null, app: AppKeys): void {
  const keys = () => page()?.keys;
  const target: KeyTarget = {
    undo: () => keys()?.undo(),
    redo: () => keys()?.redo(),
    advance: (delta) => keys()?.advance(delta),
    stepTo: (end) => keys()?.stepTo(end),
    togglePlay: () => keys()?.togglePlay(),
    playSpeed: (delta) => keys()?.playSpeed(delta),
    fit: () => keys()?.fit(),
    zoom: (factor) => keys()?.zoom(factor),
    orbit: (yaw, pitch) => keys()?.orbit(yaw, pitch),
    presenter: () => app.presenter(),
    sidePanel: () => keys()?.sidePanel(),
    lecturerControls: () => keys()?.lecturerControls(),
    ask: () => keys()?.ask(),
    blank: () => keys()?.blank(),
    get blanked() {
      return keys()?.blanked() ?? false;
    },
    tool: (name) => keys()?.tool(name),
    clearInk: () => keys()?.clearInk(),
    dark: () => app.dark(),
    fullscreen: () => app.fullscreen(),
    help: () => app.help(),
    gallery: () => app.gallery(),
  };
  window.addEventListener(
    'keydown',
    (e) => {
      if (app.helpOpen()) return;
      if (target.blanked && restoresBlank(e)) {
        keys()?.unblank();
        e.preventDefault();
        e.stopPropagation();
        return;
      }
      const binding = bindingFor(e, page() !== null);
      if (!binding) return;
      e.preventDefault();
      e.stopPropagation();
      binding.run(target);
    },
    { capture: true },
  );
}
