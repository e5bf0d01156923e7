import { useMemo, useState } from 'react';
import { useTranslation } from 'react-i18next';
import type { WatchValue } from '../api/monitor';
import { symbolsByAddress, symbolsOf } from '../cpu/projectSymbols';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import { findScale } from '../io/analog';
import { AnalogChannel } from '../io/AnalogChannel';
import { DigitalByte } from '../io/DigitalByte';
import { ioUsage, shownBytes, type AnalogWord } from '../io/ioUsage';
import '../io/io.css';
import { InfoIcon } from '../ui/icons';
import { FORMAT_NAMES, type DisplayFormat } from './watchFormat';

const WORD_FORMATS = ['dec', 'hex', 'bin'] as const satisfies readonly DisplayFormat[];
type WordFormat = (typeof WORD_FORMATS)[number];
const FORMAT_KEY = 'nasaq.io.format';

function storedFormat(): WordFormat {
  try {
    const stored = localStorage.getItem(FORMAT_KEY);
    return (WORD_FORMATS as readonly string[]).includes(stored ?? '') ? (stored as WordFormat) : 'dec';
  } catch {
    return 'dec';
  }
}

/** The value of a watched byte or word as a number, or null while unknown. */
function numberOf(value: WatchValue | undefined): number | null {
  return value && value.error === null && typeof value.value === 'number' ? value.value : null;
}

/** The watched entries' values, as one string (a new frame with the same values renders nothing). */
function valuesKey(watch: Readonly<Record<string, WatchValue>>, entries: readonly string[]): string {
  return entries.map((entry) => numberOf(watch[entry]) ?? '').join(',');
}

/** The watch entry that shows an analog word: inputs at the module (what set_input drives). */
function analogEntry(word: AnalogWord, input: boolean): string {
  return input ? `PIW${word.byte}` : `${word.peripheral ? 'P' : ''}QW${word.byte}`;
}

/** A WORD's pattern as the module's signed INT. */
const signed = (value: number) => ((value & 0xffff) >= 0x8000 ? (value & 0xffff) - 0x10000 : value & 0xffff);

/**
 * The I/O panel, like the input and output modules of PLCSIM: the digital bytes the program uses
 * (all of them on request) as switches and lamps with their symbols, and its analog words as
 * sliders (inputs) and meters (outputs), words in the chosen format. Inputs are driven at the
 * simulated module (`set_input`) and hold until changed, as a watch table's modify of an input
 * does (backend/nasaq/cpu/COMPATIBILITY.md).
 */
export function IoPanel() {
  const { t } = useTranslation();
  const { session, sources, command } = useSession();
  const connection = useMonitor((state) => state.connection);
  const [all, setAll] = useState(false);
  const [format, setFormat] = useState<WordFormat>(storedFormat);

  const symbolList = useMemo(() => symbolsOf(sources), [sources]);
  const symbols = useMemo(() => symbolsByAddress(symbolList), [symbolList]);
  const usage = useMemo(() => ioUsage(sources), [sources]);
  const inputs = useMemo(() => shownBytes(usage.inputs, all), [usage, all]);
  const outputs = useMemo(() => shownBytes(usage.outputs, all), [usage, all]);
  const scales = useMemo(() => {
    const map = new Map<string, ReturnType<typeof findScale>>();
    for (const word of [...usage.analogInputs, ...usage.analogOutputs]) {
      const named = symbols.get(word.address) ?? symbols.get(word.address.replace(/^P/, ''));
      map.set(word.address, findScale(sources, named ? [word.address, `"${named.name}"`] : [word.address]));
    }
    return map;
  }, [usage, symbols, sources]);

  const entries = useMemo(
    () => [
      ...inputs.map((byte) => `PIB${byte}`),
      ...outputs.map((byte) => `QB${byte}`),
      ...usage.analogInputs.map((word) => analogEntry(word, true)),
      ...usage.analogOutputs.map((word) => analogEntry(word, false)),
    ],
    [inputs, outputs, usage],
  );
  useWatchEntries('io-panel', entries);
  // Strings, so that the panel renders again only when a shown value or a force changed.
  const values = useMonitor((state) => valuesKey(state.watch, entries));
  const forcesKey = useMonitor((state) =>
    (state.cpu?.forced ?? []).map((force) => `${force.address}=${force.value}`).join(','),
  );
  const numbers = useMemo(() => {
    const parts = values.split(',');
    return new Map(entries.map((entry, index) => [entry, parts[index] ? Number(parts[index]) : null]));
  }, [entries, values]);
  const forced = useMemo(
    () =>
      new Map(
        forcesKey
          .split(',')
          .filter(Boolean)
          .map((pair) => {
            const [address = '', value] = pair.split('=');
            return [address, value === '1'] as const;
          }),
      ),
    [forcesKey],
  );

  if (!session) {
    return (
      <div className="io-panel" data-testid="io-panel">
        <p className="panel-empty">
          <InfoIcon className="panel-empty__icon" />
          {t('io.noSession')}
        </p>
      </div>
    );
  }

  const disabled = connection !== 'open';
  const wordForced = (area: 'I' | 'Q', byte: number) =>
    [...forced.keys()].some((address) => address.startsWith(`${area}${byte}.`) || address.startsWith(`${area}${byte + 1}.`));
  const chooseFormat = (value: WordFormat) => {
    setFormat(value);
    try {
      localStorage.setItem(FORMAT_KEY, value);
    } catch {
      // Private mode: the choice lasts for this page only.
    }
  };
  const bytesGroup = (input: boolean, bytes: readonly number[]) => (
    <section className="io-group" aria-label={t(input ? 'io.inputs' : 'io.outputs')} data-testid={`io-group-${input ? 'inputs' : 'outputs'}`}>
      <h3 className="io-group__title">{t(input ? 'io.inputs' : 'io.outputs')}</h3>
      <div className="io-group__items">
        {bytes.length === 0 ? <p className="io-group__none">{t('io.noneUsed')}</p> : null}
        {bytes.map((byte) => (
          <DigitalByte
            key={byte}
            input={input}
            byte={byte}
            value={numbers.get(`${input ? 'PIB' : 'QB'}${byte}`) ?? null}
            symbols={symbols}
            forced={forced}
            format={format}
            disabled={disabled}
            command={command}
          />
        ))}
      </div>
    </section>
  );
  const analogGroup = (input: boolean, words: readonly AnalogWord[]) =>
    words.length === 0 ? null : (
      <section
        className="io-group"
        aria-label={t(input ? 'io.analogInputs' : 'io.analogOutputs')}
        data-testid={`io-group-analog-${input ? 'inputs' : 'outputs'}`}
      >
        <h3 className="io-group__title">{t(input ? 'io.analogInputs' : 'io.analogOutputs')}</h3>
        <div className="io-group__items">
          {words.map((word) => {
            const raw = numbers.get(analogEntry(word, input)) ?? null;
            return (
              <AnalogChannel
                key={word.address}
                input={input}
                word={word}
                symbol={symbols.get(word.address) ?? symbols.get(word.address.replace(/^P/, ''))}
                raw={raw === null ? null : signed(raw)}
                scale={scales.get(word.address) ?? null}
                forced={wordForced(input ? 'I' : 'Q', word.byte)}
                format={format}
                disabled={disabled}
                command={command}
              />
            );
          })}
        </div>
      </section>
    );

  return (
    <div className="io-panel" data-testid="io-panel">
      <div className="io-toolbar">
        <label className="io-toolbar__item" title={t('io.showAllHint')}>
          <input type="checkbox" checked={all} onChange={(event) => setAll(event.target.checked)} data-testid="io-show-all" />
          {t('io.showAll')}
        </label>
        <label className="io-toolbar__item">
          {t('io.format')}
          <select value={format} onChange={(event) => chooseFormat(event.target.value as WordFormat)} data-testid="io-format">
            {WORD_FORMATS.map((value) => (
              <option key={value} value={value}>
                {FORMAT_NAMES[value]}
              </option>
            ))}
          </select>
        </label>
      </div>
      <div className="io-panel__groups">
        {bytesGroup(true, inputs)}
        {bytesGroup(false, outputs)}
        {analogGroup(true, usage.analogInputs)}
        {analogGroup(false, usage.analogOutputs)}
      </div>
    </div>
  );
}
