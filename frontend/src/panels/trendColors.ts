/** Line colours of the trend, each at least 4.5:1 on white; the entry chips use the same ones. */
export const TREND_COLORS = ['#00707a', '#b0241b', '#1d5fa8', '#8a5300', '#6a3d9a', '#1e7239', '#ad1457', '#455a64'];
