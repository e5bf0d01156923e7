import { useTranslation } from 'react-i18next';
import { ComingBadge } from '../ui/ComingBadge';

/** Trend recording of process values over time; it needs the simulator, so it is a placeholder. */
export function TrendView() {
  const { t } = useTranslation();
  return (
    <div className="trend" data-testid="trend">
      <svg className="trend__grid" viewBox="0 0 240 80" aria-hidden="true" focusable="false" preserveAspectRatio="none">
        <path d="M0 20H240M0 40H240M0 60H240M60 0V80M120 0V80M180 0V80" />
      </svg>
      <p className="trend__message">
        <ComingBadge /> <span>{t('trend.empty')}</span>
      </p>
    </div>
  );
}
