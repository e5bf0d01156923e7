/** Names shared by the app shell and the lazily loaded Monaco chunk (kept tiny on purpose). */
export const THEME_NAME = 'nasaq-light';
