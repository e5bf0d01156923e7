/** Icons of the project tree's actions, in the style of `ui/icons.tsx` (16×16, currentColor, decorative). */
import { Icon as Glyph } from '../ui/icons';

/** Three dots: the row's actions. */
export function MoreIcon(props: { size?: number; className?: string }) {
  return (
    <Glyph {...props}>
      <circle cx="3.5" cy="8" r="1" fill="currentColor" stroke="none" />
      <circle cx="8" cy="8" r="1" fill="currentColor" stroke="none" />
      <circle cx="12.5" cy="8" r="1" fill="currentColor" stroke="none" />
    </Glyph>
  );
}

/** An arrow into a tray: import. */
export function ImportIcon(props: { size?: number; className?: string }) {
  return (
    <Glyph {...props}>
      <path d="M8 2v8M5 7l3 3 3-3" />
      <path d="M2.5 10.5v2.5h11v-2.5" />
    </Glyph>
  );
}

/** A source file: a page with lines of code. */
export function SourceFileIcon(props: { size?: number; className?: string }) {
  return (
    <Glyph {...props}>
      <path d="M4 1.5h5.5L12.5 4.5v10H4z" />
      <path d="M6 8h2M7 10.5h3.5" />
    </Glyph>
  );
}

/** A block: a box with an input and an output. */
export function BlockIcon(props: { size?: number; className?: string }) {
  return (
    <Glyph {...props}>
      <rect x="4" y="3" width="8" height="10" rx="1" />
      <path d="M1.5 6h2.5M12 10h2.5" />
    </Glyph>
  );
}
