/**
 * The operand field over the element (or pin) being typed on, placed on the drawing of the view
 * (LAD grid or FBD layout), with the completions of that field.
 */
import { useTranslation } from 'react-i18next';
import { fieldText } from './fields';
import { findById } from './ladCommands';
import type { Network } from './model';
import { OperandEditor, type Complete } from './OperandEditor';
import { fieldPosition, type DiagramMode } from './positions';

/** The field being typed: an element's (or `header` for the network's title, comment, label, STL). */
export interface Editing {
  block: number;
  network: number;
  id: string;
  field: string;
}

/** The field editor over the element being typed on. */
export function FieldEditor({ edit, network, mode, completer, onCommit, onCancel }: { edit: Editing; network: Network; mode: DiagramMode; completer: Complete; onCommit: (edit: Editing, text: string) => void; onCancel: () => void }) {
  const { t } = useTranslation();
  const element = findById(network, edit.id);
  if (!element) return null;
  const { x, y } = fieldPosition(network, mode, edit.id, edit.field);
  return (
    <OperandEditor
      key={`${edit.id}:${edit.field}`}
      initial={fieldText(element, edit.field)}
      label={t(`lad.fields.${edit.field.startsWith('pin:') ? 'pin' : edit.field}`, { pin: edit.field.slice(4) })}
      complete={completer}
      onCommit={(text) => onCommit(edit, text)}
      onCancel={onCancel}
      style={{ position: 'absolute', left: x, top: y }}
    />
  );
}
