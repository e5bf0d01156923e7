import { memo, useMemo } from 'react';
import { useTranslation } from 'react-i18next';
import type { WatchValue } from '../api/monitor';
import type { MonitorCommand } from '../api/monitorClient';
import { shownIoBytes, symbolsByAddress, symbolsOf, usedIoBytes, type SymbolEntry } from '../cpu/projectSymbols';
import { useMonitor, useSession, useWatchEntries } from '../cpu/SessionContext';
import { InfoIcon } from '../ui/icons';

const BITS = [0, 1, 2, 3, 4, 5, 6, 7] as const;

/** The value of a watched byte as a number, or null while unknown. */
function byteOf(value: WatchValue | undefined): number | null {
  return value && value.error === null && typeof value.value === 'number' ? value.value & 0xff : null;
}

interface BitProps {
  address: string;
  symbol: SymbolEntry | undefined;
  on: boolean | null;
  forced: boolean;
}

type Command = (command: MonitorCommand) => Promise<unknown>;

/**
 * One input switch. Memoised, like the lamps: frames come up to 30 times a second and most of
 * them change no I/O bit, so only the bits whose props changed render again.
 */
const InputBit = memo(function InputBit({
  address,
  symbol,
  on,
  forced,
  disabled,
  command,
}: BitProps & { disabled: boolean; command: Command }) {
  const { t } = useTranslation();
  const name = symbol ? `${address} ${symbol.name}` : address;
  // A forced input only changes by forcing it again; a free one is driven like a field device.
  const onToggle = () =>
    void command(forced ? { type: 'force', address, value: !on } : { type: 'set_input', address, value: !on });
  const onForce = () =>
    void command(forced ? { type: 'unforce', address } : { type: 'force', address, value: on === true });
  return (
    <div className={`io-bit io-bit--input${on ? ' io-bit--on' : ''}${forced ? ' io-bit--forced' : ''}`}>
      <button
        type="button"
        role="switch"
        aria-checked={on === true}
        aria-label={name}
        className="io-switch"
        data-testid={`io-${address}`}
        data-state={on === null ? 'unknown' : on ? 'on' : 'off'}
        title={symbol?.comment ? `${name}: ${symbol.comment}` : name}
        disabled={disabled}
        onClick={onToggle}
      >
        <span className="io-switch__track" aria-hidden="true">
          <span className="io-switch__knob" />
        </span>
      </button>
      <span className="io-bit__foot">
        <span className="io-bit__address" aria-hidden="true">
          {address.slice(address.indexOf('.'))}
        </span>
        <button
          type="button"
          className="io-force"
          aria-pressed={forced}
          aria-label={t(forced ? 'io.unforceBit' : 'io.forceBit', { address })}
          title={t(forced ? 'io.unforceBit' : 'io.forceBit', { address })}
          data-testid={`io-force-${address}`}
          disabled={disabled}
          onClick={onForce}
        >
          F
        </button>
      </span>
      {forced ? (
        <span className="force-marker" data-testid={`io-forced-${address}`} title={t('watch.forced')}>
          <span aria-hidden="true">F</span>
          <span className="visually-hidden">{t('watch.forced')}</span>
        </span>
      ) : null}
    </div>
  );
});

const OutputBit = memo(function OutputBit({ address, symbol, on, forced }: BitProps) {
  const { t } = useTranslation();
  const name = symbol ? `${address} ${symbol.name}` : address;
  const state = on === null ? t('io.unknown') : on ? t('io.on') : t('io.off');
  return (
    <div className={`io-bit io-bit--output${forced ? ' io-bit--forced' : ''}`}>
      <span
        role="img"
        className={`io-lamp${on ? ' io-lamp--on' : ''}`}
        data-testid={`io-${address}`}
        data-state={on === null ? 'unknown' : on ? 'on' : 'off'}
        aria-label={`${name}: ${state}`}
        title={symbol?.comment ? `${name}: ${symbol.comment}` : name}
      />
      <span className="io-bit__address" aria-hidden="true">
        {address.slice(address.indexOf('.'))}
      </span>
      {forced ? (
        <span className="force-marker" data-testid={`io-forced-${address}`} title={t('watch.forced')}>
          <span aria-hidden="true">F</span>
          <span className="visually-hidden">{t('watch.forced')}</span>
        </span>
      ) : null}
    </div>
  );
});

/** The watched bytes' values, as one string (a new frame with the same values renders nothing). */
function bytesKey(watch: Readonly<Record<string, WatchValue>>, entries: readonly string[]): string {
  return entries.map((entry) => byteOf(watch[entry]) ?? '').join(',');
}

/**
 * The I/O panel, like the input and output modules of PLCSIM: the input bytes as switches
 * (click: `set_input`; F: force the bit, or remove its force) and the output bytes as lamps.
 * IB0..IB3 and QB0..QB3 are always there, and any other I/O byte the program uses.
 */
export function IoPanel() {
  const { t } = useTranslation();
  const { session, sources, command } = useSession();
  const connection = useMonitor((state) => state.connection);

  const symbols = useMemo(() => symbolsByAddress(symbolsOf(sources)), [sources]);
  const bytes = useMemo(() => shownIoBytes(usedIoBytes(sources)), [sources]);
  // The switches show the peripheral inputs (what set_input drives); the lamps the outputs.
  const entries = useMemo(
    () => [...bytes.inputs.map((byte) => `PIB${byte}`), ...bytes.outputs.map((byte) => `QB${byte}`)],
    [bytes],
  );
  useWatchEntries('io-panel', entries);
  // Strings, so that the panel renders again only when a shown byte or a force changed.
  const values = useMonitor((state) => bytesKey(state.watch, entries));
  const forcesKey = useMonitor((state) =>
    (state.cpu?.forced ?? []).map((force) => `${force.address}=${force.value}`).join(','),
  );
  const byteValues = useMemo(() => {
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

  const online = connection === 'open';
  const bitOf = (byte: number | null, bit: number) => (byte === null ? null : ((byte >> bit) & 1) === 1);

  return (
    <div className="io-panel" data-testid="io-panel">
      <section className="io-group" aria-label={t('io.inputs')}>
        <h3 className="io-group__title">{t('io.inputs')}</h3>
        {bytes.inputs.map((byte) => {
          const value = byteValues.get(`PIB${byte}`) ?? null;
          return (
            <div className="io-byte" key={byte} role="group" aria-label={`IB${byte}`} dir="ltr">
              <span className="io-byte__name">IB{byte}</span>
              {BITS.map((bit) => {
                const address = `I${byte}.${bit}`;
                const isForced = forced.has(address);
                const on = isForced ? forced.get(address)! : bitOf(value, bit);
                return (
                  <InputBit
                    key={bit}
                    address={address}
                    symbol={symbols.get(address)}
                    on={on}
                    forced={isForced}
                    disabled={!online}
                    command={command}
                  />
                );
              })}
            </div>
          );
        })}
      </section>
      <section className="io-group" aria-label={t('io.outputs')}>
        <h3 className="io-group__title">{t('io.outputs')}</h3>
        {bytes.outputs.map((byte) => {
          const value = byteValues.get(`QB${byte}`) ?? null;
          return (
            <div className="io-byte" key={byte} role="group" aria-label={`QB${byte}`} dir="ltr">
              <span className="io-byte__name">QB{byte}</span>
              {BITS.map((bit) => {
                const address = `Q${byte}.${bit}`;
                return (
                  <OutputBit
                    key={bit}
                    address={address}
                    symbol={symbols.get(address)}
                    on={bitOf(value, bit)}
                    forced={forced.has(address)}
                  />
                );
              })}
            </div>
          );
        })}
      </section>
    </div>
  );
}
