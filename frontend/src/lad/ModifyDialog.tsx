/**
 * "Modify value" from the diagram's menu: the value to write once into an operand of the running
 * program (a box pin's word, a counter's preset), in the forms the watch table takes (5, -3,
 * 16#FF, 2#1010, 1.5, T#2S, S5T#10S). The dialog follows the interface language; the operand and
 * the value stay left to right.
 */
import { useId, useRef, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { useUiLanguage } from '../i18n/useDocumentLanguage';
import { Dialog } from '../ui/Dialog';

export function ModifyDialog({ operand, onModify, onClose }: { operand: string; onModify: (value: string) => void; onClose: () => void }) {
  const { t } = useTranslation();
  const { dir, language } = useUiLanguage();
  const inputId = useId();
  const input = useRef<HTMLInputElement>(null);
  const [value, setValue] = useState('');
  const submit = (event: FormEvent) => {
    event.preventDefault();
    if (value.trim() === '') return;
    onModify(value.trim());
    onClose();
  };
  return (
    <Dialog
      title={t('lad.modify.title', { operand })}
      onClose={onClose}
      testId="lad-modify-dialog"
      initialFocus={input}
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button type="submit" form={`${inputId}-form`} className="button button--primary" data-testid="lad-modify-save">
            {t('lad.modify.save')}
          </button>
        </>
      }
    >
      <form id={`${inputId}-form`} onSubmit={submit} dir={dir} lang={language}>
        <label htmlFor={inputId}>{t('lad.modify.value')}</label>
        <input
          id={inputId}
          ref={input}
          className="input"
          dir="ltr"
          spellCheck={false}
          autoComplete="off"
          placeholder="100"
          value={value}
          onChange={(event) => setValue(event.target.value)}
          data-testid="lad-modify-value"
        />
      </form>
    </Dialog>
  );
}
