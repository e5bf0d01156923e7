/** Icons of the CPU panel and the monitoring panels, drawn like ui/icons (16×16, currentColor). */
import { Icon, type IconProps } from '../ui/icons';

/** Download into the CPU: an arrow into a module. */
export function DownloadIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M8 1.5v8M5 6.5l3 3 3-3" />
      <rect x="2.5" y="11" width="11" height="3.5" rx="0.8" />
    </Icon>
  );
}

/** Warm restart: a circular arrow. */
export function RestartIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M12.5 8A4.5 4.5 0 1 1 11 4.6" />
      <path d="M11.5 1.8v3h-3" />
    </Icon>
  );
}

/** Continue from a hold: play with a bar before it. */
export function ContinueIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M3.5 3.5v9" strokeWidth={1.8} />
      <path d="M6.5 3.5v9l6.5-4.5z" fill="currentColor" />
    </Icon>
  );
}

/** Inputs and outputs: a terminal strip. */
export function IoIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <rect x="2" y="3" width="12" height="10" rx="1" />
      <circle cx="5.5" cy="8" r="1.3" />
      <circle cx="10.5" cy="8" r="1.3" fill="currentColor" />
    </Icon>
  );
}

export function TrashIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M3 4.5h10M6.5 4.5V3h3v1.5M4.5 4.5l.6 9h5.8l.6-9" />
    </Icon>
  );
}

export function ExportIcon(props: IconProps) {
  return (
    <Icon {...props}>
      <path d="M8 10V2M5 5l3-3 3 3" />
      <path d="M3 9.5v4h10v-4" />
    </Icon>
  );
}
