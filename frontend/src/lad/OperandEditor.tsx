/**
 * The operand field typed on a diagram element (Enter on a contact, a double click on a pin):
 * an input with the completions of the STL editor (the block's members as `#name`, symbols,
 * DB members after `"Db".`), or of a fixed list (box types, status bits). Enter or Tab takes the
 * text (or the highlighted completion), Escape leaves the element as it was.
 */
import { useEffect, useId, useMemo, useRef, useState, type KeyboardEvent } from 'react';
import { useTranslation } from 'react-i18next';

export interface OperandOption {
  label: string;
  insert: string;
  detail?: string;
}

/** The completions for the text typed so far and the range of it they replace (1-based, [from, to)). */
export type Complete = (typed: string) => { from: number; to: number; options: readonly OperandOption[] };

export interface OperandEditorProps {
  initial: string;
  label: string;
  complete: Complete;
  /** Checks the text before it is taken; a message keeps the field open. */
  validate?: (text: string) => string | null;
  onCommit: (text: string) => void;
  onCancel: () => void;
  style?: React.CSSProperties;
  /** False: a field that stays in place (a table cell): no focus on mount, suggestions while focused. */
  autoFocus?: boolean;
  /** A problem of the value the field holds (marked on the input, shown as its title). */
  problem?: string | null;
}

const MAX_OPTIONS = 50;

export function OperandEditor({ initial, label, complete, validate, onCommit, onCancel, style, autoFocus = true, problem = null }: OperandEditorProps) {
  const { t } = useTranslation();
  const [text, setText] = useState(initial);
  const [active, setActive] = useState(0);
  const [error, setError] = useState<string | null>(null);
  const [open, setOpen] = useState(autoFocus);
  /** The user moved in the list: Enter takes the highlighted completion, else the typed text. */
  const [navigated, setNavigated] = useState(false);
  const input = useRef<HTMLInputElement>(null);
  const listId = useId();
  const done = useRef(false);

  useEffect(() => {
    if (!autoFocus) return;
    input.current?.focus();
    input.current?.select();
  }, [autoFocus]);

  const found = useMemo(() => {
    const result = complete(text);
    const typed = text.slice(result.from - 1, result.to - 1).toLowerCase().replace(/^"/, '');
    const options = result.options
      .filter((option) => option.insert.toLowerCase().replace(/^"|^#/, '').startsWith(typed.replace(/^#/, '')) || option.label.toLowerCase().includes(typed))
      .slice(0, MAX_OPTIONS);
    return { ...result, options };
  }, [complete, text]);
  const options = open ? found.options : [];
  const shown = Math.min(active, Math.max(0, options.length - 1));

  function apply(option: OperandOption): string {
    return text.slice(0, found.from - 1) + option.insert + text.slice(found.to - 1);
  }

  function commit(value: string) {
    const problem = validate?.(value.trim()) ?? null;
    if (problem) {
      setError(problem);
      return;
    }
    done.current = true;
    onCommit(value.trim());
  }

  function onKeyDown(event: KeyboardEvent<HTMLInputElement>) {
    event.stopPropagation();
    if (event.key === 'Escape') {
      event.preventDefault();
      if (open && options.length > 0) {
        setOpen(false);
        return;
      }
      done.current = true;
      onCancel();
    } else if (event.key === 'ArrowDown' || event.key === 'ArrowUp') {
      event.preventDefault();
      setOpen(true);
      setNavigated(true);
      const count = options.length;
      if (count > 0) setActive((shown + (event.key === 'ArrowDown' ? 1 : count - 1)) % count);
    } else if (event.key === 'Enter' || event.key === 'Tab') {
      event.preventDefault();
      const chosen = options.length > 0 && (event.key === 'Tab' || navigated) ? options[shown] : undefined;
      commit(chosen ? apply(chosen) : text);
    }
  }

  return (
    <div className="operand-editor" style={style} dir="ltr">
      <input
        ref={input}
        className="input operand-editor__input"
        role="combobox"
        aria-label={label}
        aria-expanded={options.length > 0}
        aria-controls={listId}
        aria-autocomplete="list"
        aria-activedescendant={options.length > 0 ? `${listId}-${shown}` : undefined}
        aria-invalid={error || problem ? true : undefined}
        title={problem ?? undefined}
        spellCheck={false}
        autoComplete="off"
        value={text}
        data-testid="operand-input"
        onChange={(event) => {
          setText(event.target.value);
          setActive(0);
          setOpen(true);
          setNavigated(false);
          setError(null);
        }}
        onKeyDown={onKeyDown}
        onFocus={() => {
          if (!autoFocus) setOpen(true);
        }}
        onBlur={() => {
          if (!autoFocus) setOpen(false);
          if (!done.current) commit(text);
        }}
      />
      {error ? (
        <p className="operand-editor__error" role="alert">
          {error}
        </p>
      ) : null}
      <ul id={listId} role="listbox" className="operand-editor__list" aria-label={t('lad.operand.suggestions')} hidden={options.length === 0}>
        {options.map((option, k) => (
          <li
            key={`${option.insert}-${k}`}
            id={`${listId}-${k}`}
            role="option"
            aria-selected={k === shown}
            className="operand-editor__option"
            onMouseDown={(event) => {
              event.preventDefault();
              commit(apply(option));
            }}
          >
            <span className="operand-editor__label">{option.label}</span>
            {option.detail ? <span className="operand-editor__detail">{option.detail}</span> : null}
          </li>
        ))}
      </ul>
    </div>
  );
}
