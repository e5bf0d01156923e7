import { useId, useRef, useState, type FormEvent } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, createProject, type ApiError } from '../api/client';
import type { Project } from '../api/types';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { Dialog } from '../ui/Dialog';
import { ErrorIcon } from '../ui/icons';

/** Same limits as the server's, so most mistakes are caught before sending. */
export const PROJECT_NAME_MAX = 64;
export const PROJECT_DESCRIPTION_MAX = 2000;

type Field = 'name' | 'description' | 'form';

export interface ShownError {
  field: Field;
  code: string | null;
  text: string;
}

/** Which part of the form an API error belongs beside. */
function fieldOf(error: ApiError): Field {
  const location = error.location ?? [];
  if (location.includes('description')) return 'description';
  if (location.includes('name') || error.key === 'project_name_taken') return 'name';
  if (error.status === 409 || error.status === 422) return 'name';
  return 'form';
}

export function FieldError({ id, error, testId }: { id: string; error: ShownError; testId: string }) {
  return (
    <p id={id} className="field__error" role="alert" data-testid={testId}>
      <ErrorIcon className="field__error-icon" />
      {error.code ? <code className="error-code">{error.code}</code> : null}
      <span>{error.text}</span>
    </p>
  );
}

interface NewProjectDialogProps {
  onClose: () => void;
  onCreated: (project: Project) => void;
}

/** "New project": a name and an optional description, stored on the server. */
export function NewProjectDialog({ onClose, onCreated }: NewProjectDialogProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const ids = useId();
  const formId = `${ids}-form`;
  const nameRef = useRef<HTMLInputElement>(null);
  const [name, setName] = useState('');
  const [description, setDescription] = useState('');
  const [submitting, setSubmitting] = useState(false);
  const [error, setError] = useState<ShownError | null>(null);

  async function onSubmit(event: FormEvent<HTMLFormElement>) {
    event.preventDefault();
    if (submitting) return;
    const trimmed = name.trim();
    if (!trimmed) {
      setError({ field: 'name', code: null, text: t('projects.form.nameRequired') });
      nameRef.current?.focus();
      return;
    }
    setSubmitting(true);
    setError(null);
    try {
      const project = await createProject({ name: trimmed, description: description.trim() });
      onCreated(project);
    } catch (caught) {
      const apiError = asApiError(caught);
      const field = fieldOf(apiError);
      setError({ field, code: apiError.code, text: errorText(apiError) });
      setSubmitting(false);
      if (field === 'name') nameRef.current?.focus();
    }
  }

  const nameErrorId = `${ids}-name-error`;
  const nameHintId = `${ids}-name-hint`;
  const descriptionErrorId = `${ids}-description-error`;
  const nameError = error?.field === 'name' ? error : null;
  const descriptionError = error?.field === 'description' ? error : null;
  const formError = error?.field === 'form' ? error : null;

  return (
    <Dialog
      title={t('projects.form.title')}
      onClose={onClose}
      testId="project-new-dialog"
      initialFocus={nameRef}
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button
            type="submit"
            form={formId}
            className="button button--primary"
            data-testid="project-create-submit"
            disabled={submitting}
          >
            {submitting ? t('projects.form.creating') : t('projects.form.create')}
          </button>
        </>
      }
    >
      <form id={formId} className="form" onSubmit={onSubmit} noValidate>
        <div className="field">
          <label className="field__label" htmlFor={`${ids}-name`}>
            {t('projects.form.name')}
          </label>
          <input
            ref={nameRef}
            id={`${ids}-name`}
            className="input"
            data-testid="project-name-input"
            type="text"
            dir="auto"
            autoComplete="off"
            spellCheck={false}
            required
            maxLength={PROJECT_NAME_MAX}
            value={name}
            aria-invalid={nameError ? true : undefined}
            aria-describedby={nameError ? `${nameErrorId} ${nameHintId}` : nameHintId}
            onChange={(event) => {
              setName(event.target.value);
              if (error?.field === 'name') setError(null);
            }}
          />
          <p id={nameHintId} className="field__hint">
            {t('projects.form.nameHint', { max: PROJECT_NAME_MAX })}
          </p>
          {nameError ? <FieldError id={nameErrorId} error={nameError} testId="project-name-error" /> : null}
        </div>
        <div className="field">
          <label className="field__label" htmlFor={`${ids}-description`}>
            {t('projects.form.description')} <span className="field__optional">{t('projects.form.optional')}</span>
          </label>
          <textarea
            id={`${ids}-description`}
            className="input input--multiline"
            data-testid="project-description-input"
            dir="auto"
            rows={3}
            maxLength={PROJECT_DESCRIPTION_MAX}
            value={description}
            aria-invalid={descriptionError ? true : undefined}
            aria-describedby={descriptionError ? descriptionErrorId : undefined}
            onChange={(event) => {
              setDescription(event.target.value);
              if (error?.field === 'description') setError(null);
            }}
          />
          {descriptionError ? (
            <FieldError id={descriptionErrorId} error={descriptionError} testId="project-description-error" />
          ) : null}
        </div>
        {formError ? <FieldError id={`${ids}-form-error`} error={formError} testId="project-form-error" /> : null}
      </form>
    </Dialog>
  );
}
