/**
 * One digital I/O byte as a card, like a module of PLCSIM's input and output windows: its eight
 * bits as switches (inputs) or lamps (outputs), each with its address and its symbol beside it,
 * and the byte's value in the chosen format. The card's bits wrap into two columns (.0-.3 and
 * .4-.7) so that a whole byte and its symbols fit a small bottom panel; a long symbol wraps
 * instead of being cut.
 */
import { memo } from 'react';
import { useTranslation } from 'react-i18next';
import type { MonitorCommand } from '../api/monitorClient';
import type { SymbolEntry } from '../cpu/projectSymbols';
import { formatValue, type DisplayFormat } from '../panels/watchFormat';

const BITS = [0, 1, 2, 3, 4, 5, 6, 7] as const;

type Command = (command: MonitorCommand) => Promise<unknown>;

interface BitProps {
  address: string;
  symbol: SymbolEntry | undefined;
  on: boolean | null;
  forced: boolean;
}

function ForceMarker({ address }: { address: string }) {
  const { t } = useTranslation();
  return (
    <span className="force-marker" data-testid={`io-forced-${address}`} title={t('watch.forced')}>
      <span aria-hidden="true">F</span>
      <span className="visually-hidden">{t('watch.forced')}</span>
    </span>
  );
}

function BitLabel({ address, symbol }: { address: string; symbol: SymbolEntry | undefined }) {
  return (
    <span className="io-bit__label" aria-hidden="true">
      <span className="io-bit__address">{address.slice(address.indexOf('.'))}</span>
      {symbol ? (
        <bdi className="io-bit__symbol" dir="auto" data-testid={`io-symbol-${address}`}>
          {symbol.name}
        </bdi>
      ) : null}
    </span>
  );
}

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
    <div className={`io-bit io-bit--input${on ? ' io-bit--on' : ''}${forced ? ' io-bit--forced' : ''}`} data-testid={`io-bit-${address}`}>
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
      <BitLabel address={address} symbol={symbol} />
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
      {forced ? <ForceMarker address={address} /> : null}
    </div>
  );
});

const OutputBit = memo(function OutputBit({ address, symbol, on, forced }: BitProps) {
  const { t } = useTranslation();
  const name = symbol ? `${address} ${symbol.name}` : address;
  const state = on === null ? t('io.unknown') : on ? t('io.on') : t('io.off');
  return (
    <div className={`io-bit io-bit--output${forced ? ' io-bit--forced' : ''}`} data-testid={`io-bit-${address}`}>
      <span
        role="img"
        className={`io-lamp${on ? ' io-lamp--on' : ''}`}
        data-testid={`io-${address}`}
        data-state={on === null ? 'unknown' : on ? 'on' : 'off'}
        aria-label={`${name}: ${state}`}
        title={symbol?.comment ? `${name}: ${symbol.comment}` : name}
      />
      <BitLabel address={address} symbol={symbol} />
      {forced ? <ForceMarker address={address} /> : null}
    </div>
  );
});

export interface DigitalByteProps {
  input: boolean;
  byte: number;
  value: number | null;
  symbols: ReadonlyMap<string, SymbolEntry>;
  /** Forced bits of the area: address → forced value. */
  forced: ReadonlyMap<string, boolean>;
  format: DisplayFormat;
  disabled: boolean;
  command: Command;
}

export const DigitalByte = memo(function DigitalByte({ input, byte, value, symbols, forced, format, disabled, command }: DigitalByteProps) {
  const area = input ? 'I' : 'Q';
  const name = `${area}B${byte}`;
  const bitOf = (bit: number) => (value === null ? null : ((value >> bit) & 1) === 1);
  return (
    <div className={`io-byte io-byte--${input ? 'input' : 'output'}`} role="group" aria-label={name} data-testid={`io-byte-${name}`} dir="ltr">
      <div className="io-byte__head">
        <span className="io-byte__name">{name}</span>
        <span className="io-byte__value" data-testid={`io-value-${name}`}>
          {value === null ? '' : formatValue(value, 'BYTE', format)}
        </span>
      </div>
      <div className="io-byte__bits">
        {BITS.map((bit) => {
          const address = `${area}${byte}.${bit}`;
          const isForced = forced.has(address);
          if (!input) {
            return <OutputBit key={bit} address={address} symbol={symbols.get(address)} on={bitOf(bit)} forced={isForced} />;
          }
          return (
            <InputBit
              key={bit}
              address={address}
              symbol={symbols.get(address)}
              on={isForced ? forced.get(address)! : bitOf(bit)}
              forced={isForced}
              disabled={disabled}
              command={command}
            />
          );
        })}
      </div>
    </div>
  );
});
