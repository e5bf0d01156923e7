/**
 * S7-Graph's Options > Block Settings for one FB: the FB parameter set and the three switches
 * that change what the FB does. Each choice says in a line what it means, since a student meets
 * them before knowing S7-Graph. Nothing changes until OK (onApply, which the shell turns into one
 * undoable edit); Cancel or Escape leaves the block as it was.
 */
import { useEffect, useId, useRef, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { Dialog } from '../ui/Dialog';
import type { Settings } from './model';
import './control.css';

export interface SettingsDialogProps {
  open: boolean;
  settings: Settings;
  onApply: (settings: Settings) => void;
  onClose: () => void;
}

/** Each set has every parameter of the one before it (SEMANTICS.md §1). */
const PARAMETER_SETS: readonly Settings['parameters'][] = ['MINIMUM', 'STANDARD', 'MAXIMUM', 'USER_DEFINED'];

type Switch = 'skip_steps' | 'acknowledge_required' | 'interlock_blocks';
const SWITCHES: readonly { field: Switch; label: string; help: string }[] = [
  { field: 'skip_steps', label: 'skipSteps', help: 'skipStepsHelp' },
  { field: 'acknowledge_required', label: 'acknowledge', help: 'acknowledgeHelp' },
  { field: 'interlock_blocks', label: 'interlockBlocks', help: 'interlockBlocksHelp' },
];

export function SettingsDialog({ open, settings, onApply, onClose }: SettingsDialogProps) {
  if (!open) return null;
  return <SettingsForm settings={settings} onApply={onApply} onClose={onClose} />;
}

function SettingsForm({ settings, onApply, onClose }: Omit<SettingsDialogProps, 'open'>) {
  const { t } = useTranslation();
  const id = useId();
  const [draft, setDraft] = useState<Settings>(settings);
  const selectRef = useRef<HTMLSelectElement>(null);
  // Opened on another block, or the block changed underneath (undo): start from what it is now.
  useEffect(() => setDraft(settings), [settings]);

  function apply(event?: FormEvent) {
    event?.preventDefault();
    const changed = (Object.keys(draft) as (keyof Settings)[]).some((key) => draft[key] !== settings[key]);
    if (changed) onApply(draft);
    onClose();
  }

  return (
    <Dialog
      title={t('graphControl.settings.title')}
      onClose={onClose}
      testId="graph-settings"
      initialFocus={selectRef}
      size="medium"
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('graphControl.settings.cancel')}
          </button>
          <button type="submit" form={`${id}-form`} className="button button--primary" data-testid="graph-settings-ok">
            {t('graphControl.settings.ok')}
          </button>
        </>
      }
    >
      <form id={`${id}-form`} className="graph-settings" onSubmit={apply}>
        <p className="graph-settings__intro">{t('graphControl.settings.intro')}</p>
        <label htmlFor={`${id}-parameters`} className="graph-settings__label">
          {t('graphControl.settings.parameters')}
        </label>
        <select
          id={`${id}-parameters`}
          ref={selectRef}
          className="input graph-settings__select"
          value={draft.parameters}
          aria-describedby={`${id}-parameters-help`}
          data-testid="graph-settings-parameters"
          onChange={(event) => setDraft({ ...draft, parameters: event.target.value as Settings['parameters'] })}
        >
          {PARAMETER_SETS.map((set) => (
            <option key={set} value={set}>
              {t(`graphControl.settings.parameterSet.${set}`)}
            </option>
          ))}
        </select>
        <p id={`${id}-parameters-help`} className="graph-settings__help" data-testid="graph-settings-parameters-help">
          {t(`graphControl.settings.parameterHelp.${draft.parameters}`)}
        </p>
        {PARAMETER_SETS.indexOf(draft.parameters) < PARAMETER_SETS.indexOf(settings.parameters) ? (
          <p className="graph-settings__warning" role="note" data-testid="graph-settings-smaller">
            {t('graphControl.settings.smallerSet')}
          </p>
        ) : null}
        {SWITCHES.map(({ field, label, help }) => (
          <div key={field} className="graph-settings__switch">
            <label>
              <input
                type="checkbox"
                checked={draft[field]}
                aria-describedby={`${id}-${field}-help`}
                data-testid={`graph-settings-${field.replace(/_/g, '-')}`}
                onChange={(event) => setDraft({ ...draft, [field]: event.target.checked })}
              />{' '}
              {t(`graphControl.settings.${label}`)}
            </label>
            <p id={`${id}-${field}-help`} className="graph-settings__help">
              {t(`graphControl.settings.${help}`)}
            </p>
          </div>
        ))}
      </form>
    </Dialog>
  );
}
