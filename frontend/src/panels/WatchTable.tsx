import { useTranslation } from 'react-i18next';
import { ComingBadge } from '../ui/ComingBadge';

const COLUMNS = ['address', 'symbol', 'format', 'monitor', 'modify'] as const;

/**
 * The watch table (as in STEP 7's "Monitor/Modify Variables"): one row per address.
 * Rows appear once the simulator can be monitored.
 */
export function WatchTable() {
  const { t } = useTranslation();
  return (
    <div className="watch">
      <table className="data-table" data-testid="watch-table">
        <caption className="visually-hidden">{t('watch.caption')}</caption>
        <thead>
          <tr>
            {COLUMNS.map((column) => (
              <th key={column} scope="col" className={`data-table__col--${column}`}>
                {t(`watch.columns.${column}`)}
              </th>
            ))}
          </tr>
        </thead>
        <tbody>
          <tr className="data-table__empty" data-testid="watch-empty">
            <td colSpan={COLUMNS.length}>
              <ComingBadge /> <span>{t('watch.empty')}</span>
            </td>
          </tr>
        </tbody>
      </table>
    </div>
  );
}
