import { useId, type ComponentType } from 'react';
import { useTranslation } from 'react-i18next';
import { ComingBadge } from '../ui/ComingBadge';
import { PlayIcon, StepIcon, StopIcon } from '../ui/icons';
import { CpuStateIndicator } from './CpuStateIndicator';
import { CURRENT_CPU_MODE } from './cpuState';

interface CpuCommand {
  id: 'run' | 'stop' | 'step';
  /** Mnemonic shown on the button; stays Latin in every language, as on the CPU's mode selector. */
  mnemonic: string;
  Icon: ComponentType<{ className?: string }>;
}

const COMMANDS: readonly CpuCommand[] = [
  { id: 'run', mnemonic: 'RUN', Icon: PlayIcon },
  { id: 'stop', mnemonic: 'STOP', Icon: StopIcon },
  { id: 'step', mnemonic: 'STEP', Icon: StepIcon },
];

/**
 * RUN / STOP / STEP for the simulated CPU and its mode. The simulator arrives in a later
 * release, so the buttons are shown disabled with the reason next to them.
 */
export function CpuToolbar() {
  const { t } = useTranslation();
  const reasonId = useId();
  const available = false;

  return (
    <div className="cpu-toolbar" role="group" aria-label={t('cpu.toolbarLabel')} data-testid="cpu-toolbar">
      <span className="cpu-toolbar__label" aria-hidden="true">
        CPU
      </span>
      {COMMANDS.map(({ id, mnemonic, Icon }) => (
        <button
          key={id}
          type="button"
          className={`cpu-button cpu-button--${id}`}
          data-testid={`cpu-${id}`}
          disabled={!available}
          aria-label={t(`cpu.${id}.label`)}
          aria-describedby={reasonId}
          title={`${t(`cpu.${id}.label`)} — ${t('cpu.unavailableReason')}`}
        >
          <Icon className="cpu-button__icon" />
          <span className="cpu-button__text">{mnemonic}</span>
        </button>
      ))}
      <CpuStateIndicator mode={CURRENT_CPU_MODE} />
      <span className="cpu-toolbar__coming" title={t('cpu.unavailableReason')}>
        <ComingBadge title={t('cpu.unavailableReason')} />
        <span id={reasonId} className="visually-hidden">
          {t('cpu.unavailableReason')}
        </span>
      </span>
    </div>
  );
}
