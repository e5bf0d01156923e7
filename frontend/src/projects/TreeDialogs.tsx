import { useId, useRef, useState, type FormEvent, type ReactNode } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, importProject, type ApiError } from '../api/client';
import type { ImportOut } from '../api/types';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { Dialog } from '../ui/Dialog';
import { FieldError, PROJECT_NAME_MAX, type ShownError } from './NewProjectDialog';

/** Longest file name the server takes (`workbench/names.py`). */
export const FILE_NAME_MAX = 128;

interface NameDialogProps {
  title: string;
  submitLabel: string;
  initialName: string;
  /** Runs the action; a thrown ApiError is shown beside the name. */
  onSubmit: (name: string) => Promise<void>;
  onClose: () => void;
  testId: string;
}

/** What differs between the name of a file and the name of a project. */
interface NameKind {
  label: string;
  hint: string;
  required: string;
  maxLength: number;
  /** File names are Latin-script paths; a project may be named in any script. */
  dir: 'ltr' | 'auto';
  /** The part selected when the field gets the focus: a file's stem keeps its suffix. */
  selectStem: boolean;
  /** Prefix of the test ids: `<prefix>-input`, `-submit`, `-error`. */
  ids: string;
}

/** Asks for a name and shows the server's refusal beside it. */
function NameDialog({ title, submitLabel, initialName, onSubmit, onClose, testId, kind }: NameDialogProps & { kind: NameKind }) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const ids = useId();
  const inputRef = useRef<HTMLInputElement>(null);
  const [name, setName] = useState(initialName);
  const [busy, setBusy] = useState(false);
  const [error, setError] = useState<ShownError | null>(null);

  async function submit(event: FormEvent<HTMLFormElement>) {
    event.preventDefault();
    if (busy) return;
    const trimmed = name.trim();
    if (!trimmed) {
      setError({ field: 'name', code: null, text: kind.required });
      inputRef.current?.focus();
      return;
    }
    setBusy(true);
    setError(null);
    try {
      await onSubmit(trimmed);
    } catch (caught) {
      const apiError = asApiError(caught);
      setError({ field: 'name', code: apiError.code, text: errorText(apiError) });
      setBusy(false);
      inputRef.current?.focus();
    }
  }

  const errorId = `${ids}-error`;
  const hintId = `${ids}-hint`;
  return (
    <Dialog
      title={title}
      onClose={onClose}
      testId={testId}
      initialFocus={inputRef}
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button type="submit" form={`${ids}-form`} className="button button--primary" disabled={busy} data-testid={`${kind.ids}-submit`}>
            {submitLabel}
          </button>
        </>
      }
    >
      <form id={`${ids}-form`} className="form" onSubmit={submit} noValidate>
        <div className="field">
          <label className="field__label" htmlFor={`${ids}-name`}>
            {kind.label}
          </label>
          <input
            ref={inputRef}
            id={`${ids}-name`}
            className="input"
            data-testid={`${kind.ids}-input`}
            type="text"
            dir={kind.dir}
            autoComplete="off"
            spellCheck={false}
            maxLength={kind.maxLength}
            value={name}
            aria-invalid={error ? true : undefined}
            aria-describedby={error ? `${errorId} ${hintId}` : hintId}
            onFocus={(event) => {
              const value = event.currentTarget.value;
              const dot = kind.selectStem ? value.lastIndexOf('.') : -1;
              event.currentTarget.setSelectionRange(0, dot > 0 ? dot : value.length);
            }}
            onChange={(event) => {
              setName(event.target.value);
              setError(null);
            }}
          />
          <p id={hintId} className="field__hint">
            {kind.hint}
          </p>
          {error ? <FieldError id={errorId} error={error} testId={`${kind.ids}-error`} /> : null}
        </div>
      </form>
    </Dialog>
  );
}

/** Asks for a file name (new source, rename, duplicate). */
export function FileNameDialog(props: NameDialogProps) {
  const { t } = useTranslation();
  const kind: NameKind = {
    label: t('projects.files.name'),
    hint: t('projects.files.nameHint', { max: FILE_NAME_MAX }),
    required: t('projects.files.nameRequired'),
    maxLength: FILE_NAME_MAX,
    dir: 'ltr',
    selectStem: true,
    ids: 'file-name',
  };
  return <NameDialog {...props} kind={kind} />;
}

/** Asks for a project's new name (unique, letter case aside; at most 64 characters). */
export function ProjectNameDialog(props: NameDialogProps) {
  const { t } = useTranslation();
  const kind: NameKind = {
    label: t('projects.form.name'),
    hint: t('projects.form.nameHint', { max: PROJECT_NAME_MAX }),
    required: t('projects.form.nameRequired'),
    maxLength: PROJECT_NAME_MAX,
    dir: 'auto',
    selectStem: false,
    ids: 'project-rename',
  };
  return <NameDialog {...props} kind={kind} />;
}

interface ConfirmDialogProps {
  title: string;
  children: ReactNode;
  confirmLabel: string;
  onConfirm: () => Promise<void>;
  onClose: () => void;
  testId: string;
}

/** "Delete …?": the action runs only on the explicit button; Cancel has the focus first. */
export function ConfirmDialog({ title, children, confirmLabel, onConfirm, onClose, testId }: ConfirmDialogProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const cancelRef = useRef<HTMLButtonElement>(null);
  const [busy, setBusy] = useState(false);
  const [error, setError] = useState<ApiError | null>(null);

  async function confirm() {
    if (busy) return;
    setBusy(true);
    setError(null);
    try {
      await onConfirm();
    } catch (caught) {
      setError(asApiError(caught));
      setBusy(false);
    }
  }

  return (
    <Dialog
      title={title}
      onClose={onClose}
      testId={testId}
      initialFocus={cancelRef}
      footer={
        <>
          <button ref={cancelRef} type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button
            type="button"
            className="button button--danger"
            disabled={busy}
            data-testid="confirm-submit"
            onClick={() => void confirm()}
          >
            {confirmLabel}
          </button>
        </>
      }
    >
      <div className="form">
        {children}
        {error ? (
          <FieldError
            id={`${testId}-error`}
            error={{ field: 'form', code: error.code, text: errorText(error) }}
            testId="confirm-error"
          />
        ) : null}
      </div>
    </Dialog>
  );
}

interface ImportDialogProps {
  onClose: () => void;
  onImported: (result: ImportOut) => void;
}

/** "Import project": a zip of sources (as `export.zip` writes it) becomes a new project. */
export function ImportDialog({ onClose, onImported }: ImportDialogProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const ids = useId();
  const fileRef = useRef<HTMLInputElement>(null);
  const nameRef = useRef<HTMLInputElement>(null);
  const [zip, setZip] = useState<File | null>(null);
  const [name, setName] = useState('');
  const [busy, setBusy] = useState(false);
  const [error, setError] = useState<ShownError | null>(null);

  async function submit(event: FormEvent<HTMLFormElement>) {
    event.preventDefault();
    if (busy) return;
    if (!zip) {
      setError({ field: 'form', code: null, text: t('projects.import.fileRequired') });
      fileRef.current?.focus();
      return;
    }
    setBusy(true);
    setError(null);
    try {
      onImported(await importProject(zip, name.trim() || undefined));
    } catch (caught) {
      const apiError = asApiError(caught);
      const byName = apiError.location?.includes('name') || apiError.code === 'API105' || apiError.code === 'API115';
      setError({ field: byName ? 'name' : 'form', code: apiError.code, text: errorText(apiError) });
      setBusy(false);
      (byName ? nameRef : fileRef).current?.focus();
    }
  }

  const nameError = error?.field === 'name' ? error : null;
  const formError = error?.field === 'form' ? error : null;
  return (
    <Dialog
      title={t('projects.import.title')}
      onClose={onClose}
      testId="project-import-dialog"
      initialFocus={fileRef}
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button
            type="submit"
            form={`${ids}-form`}
            className="button button--primary"
            disabled={busy}
            data-testid="project-import-submit"
          >
            {busy ? t('projects.import.importing') : t('projects.import.submit')}
          </button>
        </>
      }
    >
      <form id={`${ids}-form`} className="form" onSubmit={submit} noValidate>
        <div className="field">
          <label className="field__label" htmlFor={`${ids}-file`}>
            {t('projects.import.file')}
          </label>
          <input
            ref={fileRef}
            id={`${ids}-file`}
            className="input"
            data-testid="project-import-file"
            type="file"
            accept=".zip,application/zip"
            aria-describedby={`${ids}-file-hint`}
            onChange={(event) => {
              setZip(event.target.files?.[0] ?? null);
              setError(null);
            }}
          />
          <p id={`${ids}-file-hint`} className="field__hint">
            {t('projects.import.fileHint')}
          </p>
        </div>
        <div className="field">
          <label className="field__label" htmlFor={`${ids}-name`}>
            {t('projects.form.name')} <span className="field__optional">{t('projects.form.optional')}</span>
          </label>
          <input
            ref={nameRef}
            id={`${ids}-name`}
            className="input"
            data-testid="project-import-name"
            type="text"
            dir="auto"
            autoComplete="off"
            maxLength={PROJECT_NAME_MAX}
            value={name}
            aria-invalid={nameError ? true : undefined}
            aria-describedby={nameError ? `${ids}-name-error ${ids}-name-hint` : `${ids}-name-hint`}
            onChange={(event) => {
              setName(event.target.value);
              if (error?.field === 'name') setError(null);
            }}
          />
          <p id={`${ids}-name-hint`} className="field__hint">
            {t('projects.import.nameHint')}
          </p>
          {nameError ? <FieldError id={`${ids}-name-error`} error={nameError} testId="project-import-error" /> : null}
        </div>
        {formError ? <FieldError id={`${ids}-form-error`} error={formError} testId="project-import-error" /> : null}
      </form>
    </Dialog>
  );
}
