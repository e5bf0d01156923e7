/**
 * The grid layout of each network, worked out once per network object: networks are immutable
 * and an edit replaces only the networks it changed, so every other network keeps its layout
 * while a 500-network block is scrolled, monitored or edited.
 */
import { ladLayout } from './layout';
import type { LadLayout, Network } from './model';

const layouts = new WeakMap<Network, LadLayout>();

export function layoutOf(network: Network): LadLayout {
  let layout = layouts.get(network);
  if (!layout) {
    layout = ladLayout(network);
    layouts.set(network, layout);
  }
  return layout;
}
