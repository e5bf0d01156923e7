import { useTranslation } from 'react-i18next';
import type { CpuMode } from './cpuState';

/** The CPU's operating mode as a status LED and text, like the LEDs on an S7 CPU front. */
export function CpuStateIndicator({ mode }: { mode: CpuMode }) {
  const { t } = useTranslation();
  return (
    <span className={`cpu-state cpu-state--${mode}`} data-testid="cpu-state">
      <span className="led" aria-hidden="true" />
      <span className="cpu-state__text">{t(`cpu.mode.${mode}`)}</span>
    </span>
  );
}
