/**
 * One analog channel of the I/O panel. An input (IW/PIW) is a slider over the module's whole
 * range (underrange to overrange, see `analog.ts`) and a field that takes a value in decimal,
 * `16#…` or `2#…` and shows it in the chosen format; both drive the simulated module with
 * `set_input`, which holds until changed (PLCSIM's behaviour). An output (QW/PQW) is a meter the
 * program moves. Both say where the value lies (nominal, overrange …), its percent of 27648, and
 * the engineering value when the program scales the word with known limits (FC105/FC106 or a
 * project function with Low/High).
 */
import { memo, useEffect, useMemo, useState, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';
import type { MonitorCommand } from '../api/monitorClient';
import type { SymbolEntry } from '../cpu/projectSymbols';
import { formatValue, type DisplayFormat } from '../panels/watchFormat';
import { NOMINAL, parseWord, percentOf, regionOf, scaled, shortNumber, sliderRange, type Scale } from './analog';
import type { AnalogWord } from './ioUsage';
import { LatestOnly } from './latestOnly';

type Command = (command: MonitorCommand) => Promise<unknown>;

/** Arrow keys move the slider by 1 % of the nominal range, Page keys by 10 %, Shift+arrow by 1. */
function keyStep(event: KeyboardEvent): number | null {
  const percent = NOMINAL / 100;
  switch (event.key) {
    case 'ArrowUp':
    case 'ArrowRight':
      return event.shiftKey ? 1 : percent;
    case 'ArrowDown':
    case 'ArrowLeft':
      return event.shiftKey ? -1 : -percent;
    case 'PageUp':
      return percent * 10;
    case 'PageDown':
      return -percent * 10;
    default:
      return null;
  }
}

function Hints({ raw, bipolar, scale, testId }: { raw: number | null; bipolar: boolean; scale: Scale | null; testId: string }) {
  const { t } = useTranslation();
  const region = raw === null ? null : regionOf(raw, bipolar);
  return (
    <div className="io-analog__hints">
      {region ? (
        <span className={`io-analog__region io-analog__region--${region}`} data-testid={`${testId}-region`} data-region={region}>
          {t(`io.region.${region}`)}
        </span>
      ) : null}
      <span className="io-analog__hint" data-testid={`${testId}-hint`}>
        {raw === null
          ? t(bipolar ? 'io.bipolarRange' : 'io.nominalRange')
          : t('io.percent', { value: shortNumber(percentOf(raw)), range: t(bipolar ? 'io.bipolarRange' : 'io.nominalRange') })}
      </span>
      {scale ? (
        <span className="io-analog__scaled" data-testid={`${testId}-scaled`}>
          <bdi dir="ltr">{scale.block}</bdi>{' '}
          {raw === null
            ? t('io.scaleLimits', { low: shortNumber(scale.low), high: shortNumber(scale.high) })
            : t('io.scaledValue', {
                value: shortNumber(scaled(raw, { ...scale, bipolar })),
                low: shortNumber(scale.low),
                high: shortNumber(scale.high),
              })}
          {scale.target ? (
            <>
              {' '}
              {t('io.into')} <bdi dir="ltr">{scale.target}</bdi>
            </>
          ) : null}
        </span>
      ) : null}
    </div>
  );
}

export interface AnalogChannelProps {
  input: boolean;
  word: AnalogWord;
  symbol: SymbolEntry | undefined;
  /** The word as a signed INT, or null while unknown. */
  raw: number | null;
  scale: Scale | null;
  forced: boolean;
  format: DisplayFormat;
  disabled: boolean;
  command: Command;
}

export const AnalogChannel = memo(function AnalogChannel({
  input,
  word,
  symbol,
  raw,
  scale,
  forced,
  format,
  disabled,
  command,
}: AnalogChannelProps) {
  const { t } = useTranslation();
  const [bipolar, setBipolar] = useState(scale?.bipolar ?? false);
  // What the slider shows while its value is on the way to the CPU (the frame confirms it).
  const [draft, setDraft] = useState<number | null>(null);
  // The field's text while the user types in it; null: it shows the value.
  const [text, setText] = useState<string | null>(null);
  const [bad, setBad] = useState<string | null>(null);
  const name = symbol ? `${word.address} ${symbol.name}` : word.address;
  const testId = `io-analog-${word.address}`;
  const address = word.address;

  const sender = useMemo(
    () =>
      new LatestOnly<number>(async (value) => {
        const answer = await command({ type: 'set_input', address, value });
        if (answer === null) setDraft(null);
      }),
    [command, address],
  );
  // Confirmed: the frame shows the value (a newer draft, set meanwhile, stays).
  useEffect(() => {
    setDraft((current) => (current !== null && current === raw ? null : current));
  }, [raw]);

  const { min, max } = sliderRange(bipolar);
  const shown = draft ?? raw;
  const formatted = shown === null ? '' : formatValue(shown, 'INT', format);

  const send = (value: number) => {
    const clamped = Math.round(value);
    setDraft(clamped === raw ? null : clamped);
    sender.push(clamped);
  };
  const commit = () => {
    if (text === null) return;
    if (text.trim() === '') {
      setText(null);
      setBad(null);
      return;
    }
    const value = parseWord(text);
    if (value === null) {
      setBad(text);
      return;
    }
    setBad(null);
    setText(null);
    send(value);
  };
  const onSliderKey = (event: KeyboardEvent<HTMLInputElement>) => {
    const step = keyStep(event);
    if (step === null || disabled) return;
    event.preventDefault();
    send(Math.min(max, Math.max(min, (shown ?? 0) + step)));
  };

  const percent = shown === null ? 0 : Math.min(100, Math.max(0, ((shown - min) / (max - min)) * 100));
  return (
    <div className={`io-analog io-analog--${input ? 'input' : 'output'}`} role="group" aria-label={name} data-testid={testId}>
      <div className="io-analog__head" dir="ltr">
        <span className="io-analog__name">{word.address}</span>
        {symbol ? (
          <bdi className="io-analog__symbol" dir="auto" data-testid={`${testId}-symbol`} title={symbol.comment || undefined}>
            {symbol.name}
          </bdi>
        ) : null}
        {forced ? (
          <span className="force-marker" title={t('watch.forced')} data-testid={`${testId}-forced`}>
            <span aria-hidden="true">F</span>
            <span className="visually-hidden">{t('watch.forced')}</span>
          </span>
        ) : null}
      </div>
      <div className="io-analog__controls" dir="ltr">
        {input ? (
          <input
            type="range"
            className="io-analog__slider"
            min={min}
            max={max}
            step={1}
            value={shown ?? 0}
            disabled={disabled}
            aria-label={t('io.slider', { name })}
            aria-valuetext={shown === null ? t('io.unknown') : `${shown} (${shortNumber(percentOf(shown))} %)`}
            data-testid={`${testId}-slider`}
            onChange={(event) => send(Number(event.target.value))}
            onKeyDown={onSliderKey}
          />
        ) : (
          <span
            className="io-analog__meter"
            role="meter"
            aria-label={name}
            aria-valuemin={min}
            aria-valuemax={max}
            aria-valuenow={raw ?? undefined}
            data-testid={`${testId}-meter`}
          >
            <span className="io-analog__meter-fill" style={{ inlineSize: `${percent}%` }} />
          </span>
        )}
        {input ? (
          <input
            type="text"
            className={`io-analog__field io-analog__field--${format}${bad !== null ? ' io-analog__field--bad' : ''}`}
            value={text ?? formatted}
            disabled={disabled}
            spellCheck={false}
            aria-label={t('io.value', { name })}
            aria-invalid={bad !== null}
            data-testid={`${testId}-field`}
            onChange={(event) => setText(event.target.value)}
            onBlur={commit}
            onKeyDown={(event) => {
              if (event.key === 'Enter') commit();
              if (event.key === 'Escape') {
                // Back to the value; the field keeps the focus (a blur would send what was typed).
                setText(null);
                setBad(null);
              }
            }}
          />
        ) : (
          <output className={`io-analog__field io-analog__field--${format}`} data-testid={`${testId}-field`}>
            {formatted}
          </output>
        )}
      </div>
      {bad !== null ? (
        <p className="io-analog__error" role="alert" data-testid={`${testId}-error`}>
          {t('io.badWord', { text: bad })}
        </p>
      ) : null}
      <Hints raw={shown} bipolar={bipolar} scale={scale} testId={testId} />
      <label className="io-analog__bipolar">
        <input type="checkbox" checked={bipolar} onChange={(event) => setBipolar(event.target.checked)} data-testid={`${testId}-bipolar`} />
        {t('io.bipolar')}
      </label>
    </div>
  );
});
