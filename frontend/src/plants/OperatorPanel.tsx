import { useEffect, useRef, useState, type KeyboardEvent, type PointerEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { MonitorCommand } from '../api/monitorClient';
import { bcdWheels, bcdWord, controlStyle, controlsOf, pressedValue, restValue } from './controls';
import { useFaultText, useSignalName } from './parts';
import type { PlantCommand, PlantFrame, PlantInfo, PlantSignalInfo } from './types';

export type SendPlantCommand = (command: PlantCommand) => void;

/** A plant command through the session's command channel (refusals show as the session's problem). */
export function plantCommandSender(command: (message: MonitorCommand) => Promise<unknown>): SendPlantCommand {
  return (message) => void command(message);
}

/**
 * What a control shows: the value the operator just chose until the plant's frame reports it
 * (or, if the session refused it, a moment later the plant's own value again), so a switch or a
 * fault's box follows the click at once instead of waiting for the next frame.
 */
function useChosen<T>(actual: T): [T, (value: T) => void] {
  const [chosen, setChosen] = useState<{ value: T } | null>(null);
  useEffect(() => {
    if (chosen === null) return;
    if (Object.is(chosen.value, actual)) {
      setChosen(null);
      return;
    }
    const timer = setTimeout(() => setChosen(null), 1500);
    return () => clearTimeout(timer);
  }, [actual, chosen]);
  return [chosen ? chosen.value : actual, (value) => setChosen({ value })];
}

interface ControlProps {
  plant: PlantFrame;
  signal: PlantSignalInfo;
  disabled: boolean;
  send: SendPlantCommand;
}

/** A momentary push button: pressed while held by the pointer, or by Space/Enter. */
function PushButton({ plant, signal, disabled, send }: ControlProps) {
  const signalName = useSignalName();
  const [held, setHeld] = useState(false);
  const heldRef = useRef(false);
  const operate = (down: boolean) => {
    if (heldRef.current === down) return;
    heldRef.current = down;
    setHeld(down);
    send({ type: 'plant_operate', control: signal.name, value: down ? pressedValue(signal) : restValue(signal) });
  };
  // Released when the panel goes away with the button held.
  useEffect(() => () => {
    if (heldRef.current) send({ type: 'plant_operate', control: signal.name, value: restValue(signal) });
  }, []); // eslint-disable-line react-hooks/exhaustive-deps
  const active = (plant.signals[signal.name] ?? restValue(signal)) !== restValue(signal);
  const onKeyDown = (event: KeyboardEvent<HTMLButtonElement>) => {
    if ((event.key === ' ' || event.key === 'Enter') && !event.repeat) {
      event.preventDefault();
      operate(true);
    }
  };
  const onKeyUp = (event: KeyboardEvent<HTMLButtonElement>) => {
    if (event.key === ' ' || event.key === 'Enter') {
      event.preventDefault();
      operate(false);
    }
  };
  const onPointerDown = (event: PointerEvent<HTMLButtonElement>) => {
    if (event.button !== 0) return;
    event.currentTarget.setPointerCapture?.(event.pointerId);
    operate(true);
  };
  return (
    <button
      type="button"
      className={`plant-control plant-control--button${signal.normally_closed ? ' plant-control--nc' : ''}${held || active ? ' plant-control--pressed' : ''}`}
      aria-pressed={held}
      disabled={disabled}
      data-testid={`plant-control-${signal.name}`}
      onPointerDown={onPointerDown}
      onPointerUp={() => operate(false)}
      onPointerCancel={() => operate(false)}
      onLostPointerCapture={() => operate(false)}
      onKeyDown={onKeyDown}
      onKeyUp={onKeyUp}
      onBlur={() => operate(false)}
      onClick={(event) => event.preventDefault()}
    >
      <span className="plant-control__cap" aria-hidden="true" />
      <span className="plant-control__name">{signalName(signal.name)}</span>
      <bdi className="plant-control__address">{plant.wiring[signal.name] ?? ''}</bdi>
    </button>
  );
}

/** A selector switch: stays where it was turned. */
function Switch({ plant, signal, disabled, send }: ControlProps) {
  const signalName = useSignalName();
  const [on, choose] = useChosen((plant.signals[signal.name] ?? 0) !== 0);
  return (
    <label className={on ? 'plant-control plant-control--switch plant-control--pressed' : 'plant-control plant-control--switch'}>
      <input
        type="checkbox"
        role="switch"
        checked={on}
        disabled={disabled}
        data-testid={`plant-control-${signal.name}`}
        onChange={(event) => {
          choose(event.target.checked);
          send({ type: 'plant_operate', control: signal.name, value: event.target.checked ? 1 : 0 });
        }}
      />
      <span className="plant-control__name">{signalName(signal.name)}</span>
      <bdi className="plant-control__address">{plant.wiring[signal.name] ?? ''}</bdi>
    </label>
  );
}

/** BCD thumbwheels: one digit per wheel, thousands first. */
function Thumbwheels({ plant, signal, disabled, send }: ControlProps) {
  const { t } = useTranslation();
  const signalName = useSignalName();
  const digits = bcdWheels(plant.signals[signal.name] ?? 0);
  return (
    <fieldset className="plant-control plant-control--wheels" data-testid={`plant-control-${signal.name}`}>
      <legend className="plant-control__name">
        {signalName(signal.name)} <bdi className="plant-control__address">{plant.wiring[signal.name] ?? ''}</bdi>
      </legend>
      <div className="plant-wheels" dir="ltr">
        {digits.map((digit, index) => (
          <input
            key={index}
            type="number"
            min={0}
            max={9}
            step={1}
            value={digit}
            disabled={disabled}
            aria-label={t('plants.panel.digit', { position: index + 1, name: signalName(signal.name) })}
            data-testid={`plant-wheel-input-${index}`}
            onChange={(event) => {
              const next = [...digits];
              next[index] = Math.min(9, Math.max(0, Math.trunc(Number(event.target.value) || 0)));
              send({ type: 'plant_operate', control: signal.name, value: bcdWord(next) });
            }}
          />
        ))}
      </div>
    </fieldset>
  );
}

/** A word set by number (an analog set-point the operator turns). */
function NumberControl({ plant, signal, disabled, send }: ControlProps) {
  const signalName = useSignalName();
  const value = plant.signals[signal.name] ?? 0;
  return (
    <label className="plant-control plant-control--number">
      <span className="plant-control__name">{signalName(signal.name)}</span>
      <input
        type="number"
        min={0}
        max={32767}
        value={value}
        disabled={disabled}
        data-testid={`plant-control-${signal.name}`}
        onChange={(event) => send({ type: 'plant_operate', control: signal.name, value: Math.min(32767, Math.max(-32768, Math.trunc(Number(event.target.value) || 0))) })}
      />
    </label>
  );
}

/** One injectable fault in the menu: checked while it is active. */
function FaultItem({ code, active, label, send }: { code: string; active: boolean; label: string; send: SendPlantCommand }) {
  const [checked, choose] = useChosen(active);
  return (
    <label className="plant-faults-menu__item">
      <input
        type="checkbox"
        checked={checked}
        data-testid={`plant-inject-${code}`}
        onChange={(event) => {
          choose(event.target.checked);
          send({ type: 'plant_fault', fault: code, on: event.target.checked });
        }}
      />
      {label}
    </label>
  );
}

interface OperatorPanelProps {
  plant: PlantFrame;
  info: PlantInfo | undefined;
  disabled: boolean;
  send: SendPlantCommand;
}

/**
 * The plant's operator panel: its push buttons and switches, the faults a teacher or learner can
 * inject, and a reset that puts the process back to its start (PLCSIM's "reset" of a plant).
 */
export function OperatorPanel({ plant, info, disabled, send }: OperatorPanelProps) {
  const { t } = useTranslation();
  const faultText = useFaultText();
  const [faultsOpen, setFaultsOpen] = useState(false);
  const menu = useRef<HTMLDivElement>(null);
  // The fault menu closes on Escape and on a click anywhere else, as a menu does.
  useEffect(() => {
    if (!faultsOpen) return;
    const onPointer = (event: globalThis.PointerEvent) => {
      if (!menu.current?.contains(event.target as Node)) setFaultsOpen(false);
    };
    document.addEventListener('pointerdown', onPointer);
    return () => document.removeEventListener('pointerdown', onPointer);
  }, [faultsOpen]);
  const controls = info ? controlsOf(info) : [];
  const injectable = info ? info.faults.filter((fault) => fault.injectable) : [];
  return (
    <div className="plant-operator" role="group" aria-label={t('plants.panel.label')} data-testid="plant-operator">
      <div className="plant-operator__controls">
        {controls.map((signal) => {
          const props = { plant, signal, disabled, send };
          switch (controlStyle(plant.kind, signal)) {
            case 'switch':
              return <Switch key={signal.name} {...props} />;
            case 'thumbwheel':
              return <Thumbwheels key={signal.name} {...props} />;
            case 'number':
              return <NumberControl key={signal.name} {...props} />;
            default:
              return <PushButton key={signal.name} {...props} />;
          }
        })}
      </div>
      <div className="plant-operator__actions">
        {injectable.length > 0 ? (
          <div
            className="plant-faults-menu"
            ref={menu}
            onKeyDown={(event) => {
              if (event.key === 'Escape' && faultsOpen) {
                event.stopPropagation();
                setFaultsOpen(false);
                menu.current?.querySelector('button')?.focus();
              }
            }}
          >
            <button
              type="button"
              className="button button--small"
              aria-expanded={faultsOpen}
              aria-haspopup="true"
              disabled={disabled}
              data-testid="plant-faults-button"
              onClick={() => setFaultsOpen(!faultsOpen)}
            >
              {t('plants.panel.faults')}
            </button>
            {faultsOpen ? (
              <div className="plant-faults-menu__list" role="group" aria-label={t('plants.panel.faults')} data-testid="plant-faults-menu">
                {injectable.map((fault) => (
                  <FaultItem key={fault.code} code={fault.code} active={plant.faults.includes(fault.code)} label={faultText(plant.kind, fault.code, fault.description)} send={send} />
                ))}
              </div>
            ) : null}
          </div>
        ) : null}
        <button type="button" className="button button--small" disabled={disabled} data-testid="plant-reset" onClick={() => send({ type: 'plant_reset' })}>
          {t('plants.panel.reset')}
        </button>
      </div>
    </div>
  );
}
