import { useTranslation } from 'react-i18next';

/** Marks a feature that is visible today but arrives in a later release. */
export function ComingBadge({ id, title }: { id?: string; title?: string }) {
  const { t } = useTranslation();
  return (
    <span className="badge badge--coming" id={id} title={title ?? t('common.comingTitle')}>
      {t('common.coming')}
    </span>
  );
}
