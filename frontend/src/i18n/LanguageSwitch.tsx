import { useId } from 'react';
import { useTranslation } from 'react-i18next';
import { GlobeIcon } from '../ui/icons';
import { LANGUAGES, directionOf, isLanguage, nativeNameOf } from './languages';
import { chooseLanguage } from './setup';
import { useUiLanguage } from './useDocumentLanguage';

/** The interface language, each option written in its own language. */
export function LanguageSwitch() {
  const { t, i18n } = useTranslation();
  const { language } = useUiLanguage();
  const id = useId();

  return (
    <div className="language-switch">
      <label htmlFor={id} className="language-switch__label" title={t('topbar.language')}>
        <GlobeIcon />
        <span className="visually-hidden">{t('topbar.language')}</span>
      </label>
      <select
        id={id}
        className="select select--dark"
        data-testid="lang-switch"
        value={language}
        onChange={(event) => {
          const next = event.target.value;
          if (isLanguage(next)) void chooseLanguage(i18n, next);
        }}
      >
        {LANGUAGES.map((code) => (
          <option key={code} value={code} lang={code} dir={directionOf(code)}>
            {nativeNameOf(code)}
          </option>
        ))}
      </select>
    </div>
  );
}
