import { useId, useMemo, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { asApiError, deleteFile, saveFile, type ApiError } from '../api/client';
import type { FileInfo } from '../api/types';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { nameTaken } from '../projects/fileNames';
import { projectContents } from '../projects/projectContents';
import { Dialog } from '../ui/Dialog';
import { DRAWINGS } from './drawings';
import { plantFileName, writePlantFile } from './plantFile';
import { useSignalName } from './parts';
import type { PlantConfig, PlantInfo } from './types';
import { normalAddress, wireProblem } from './wiring';

interface AttachPlantDialogProps {
  projectId: number;
  files: readonly FileInfo[];
  plants: readonly PlantInfo[];
  /** The plant file being edited (its name and what it holds), or null to attach a new one. */
  editing: { name: string; config: PlantConfig } | null;
  onClose: () => void;
  onSaved: (name: string) => void;
}

function startWiring(info: PlantInfo | undefined, config: PlantConfig | null): Record<string, string> {
  if (!info) return {};
  const wiring = config && config.kind === info.kind ? config.wiring : info.default_wiring;
  return Object.fromEntries(info.signals.map((signal) => [signal.name, wiring[signal.name] ?? '']));
}

function startParams(info: PlantInfo | undefined, config: PlantConfig | null): Record<string, string> {
  if (!info) return {};
  const params = config && config.kind === info.kind ? config.params : {};
  return Object.fromEntries(Object.entries(info.defaults).map(([name, value]) => [name, String(params[name] ?? value)]));
}

/**
 * "Attach a plant…": the kind, its wiring (prefilled with the course's usual addresses) and its
 * parameters, saved as `<kind>.plant` in the project. Editing an attached plant opens it with its
 * own values; changing the kind renames the file.
 */
/** The kinds in the order of the course (the drawings' order), then any other. */
function courseOrder(plants: readonly PlantInfo[]): PlantInfo[] {
  const order = Object.keys(DRAWINGS);
  const rank = (kind: string) => (order.includes(kind) ? order.indexOf(kind) : order.length);
  return [...plants].sort((a, b) => rank(a.kind) - rank(b.kind) || a.kind.localeCompare(b.kind));
}

export function AttachPlantDialog({ projectId, files, plants: given, editing, onClose, onSaved }: AttachPlantDialogProps) {
  const { t } = useTranslation();
  const kindId = useId();
  const plants = useMemo(() => courseOrder(given), [given]);
  const signalName = useSignalName();
  const errorText = useApiErrorText();
  const [kind, setKind] = useState(editing?.config.kind ?? plants[0]?.kind ?? '');
  const info = plants.find((plant) => plant.kind === kind);
  const [wiring, setWiring] = useState(() => startWiring(info, editing?.config ?? null));
  const [params, setParams] = useState(() => startParams(info, editing?.config ?? null));
  const [busy, setBusy] = useState(false);
  const [error, setError] = useState<ApiError | null>(null);

  const chooseKind = (next: string) => {
    const nextInfo = plants.find((plant) => plant.kind === next);
    setKind(next);
    setWiring(startWiring(nextInfo, editing?.config ?? null));
    setParams(startParams(nextInfo, editing?.config ?? null));
  };

  const problems = useMemo(
    () => Object.fromEntries((info?.signals ?? []).map((signal) => [signal.name, wireProblem(signal, wiring[signal.name] ?? '')])),
    [info, wiring],
  );
  const badParams = Object.entries(params).filter(([, text]) => text.trim() === '' || !Number.isFinite(Number(text))).map(([name]) => name);
  const name = plantFileName(kind);
  const clash = nameTaken(files, name, editing?.name);
  const invalid = !info || Object.values(problems).some((problem) => problem !== null) || badParams.length > 0 || clash;

  async function save() {
    if (!info || invalid || busy) return;
    setBusy(true);
    setError(null);
    const config: PlantConfig = {
      kind,
      wiring: Object.fromEntries(Object.entries(wiring).map(([signal, address]) => [signal, normalAddress(address)])),
      params: Object.fromEntries(
        Object.entries(params)
          .map(([param, text]) => [param, Number(text)] as const)
          .filter(([param, value]) => value !== info.defaults[param]),
      ),
      faults: editing && editing.config.kind === kind ? editing.config.faults : [],
    };
    try {
      const saved = await saveFile(projectId, name, { text: writePlantFile(config) });
      projectContents.putFile(projectId, saved);
      if (editing && editing.name !== name) {
        await deleteFile(projectId, editing.name);
        projectContents.removeFile(projectId, editing.name);
      }
      projectContents.reloadSoon(projectId);
      onSaved(name);
    } catch (caught) {
      setError(asApiError(caught));
      setBusy(false);
    }
  }

  const problemText = (problem: NonNullable<ReturnType<typeof wireProblem>>) => t(`plants.attach.wire.${problem}`);

  return (
    <Dialog
      title={editing ? t('plants.attach.editTitle') : t('plants.attach.title')}
      onClose={onClose}
      testId="attach-plant-dialog"
      size="medium"
      footer={
        <>
          <button type="button" className="button" onClick={onClose}>
            {t('common.cancel')}
          </button>
          <button type="button" className="button button--primary" disabled={invalid || busy} data-testid="attach-plant-save" onClick={() => void save()}>
            {editing ? t('plants.attach.save') : t('plants.attach.attach')}
          </button>
        </>
      }
    >
      <form
        className="form plant-attach"
        onSubmit={(event) => {
          event.preventDefault();
          void save();
        }}
      >
        <div className="field">
          <label className="field__label" htmlFor={kindId}>
            {t('plants.attach.kind')}
          </label>
          <select id={kindId} className="input" value={kind} onChange={(event) => chooseKind(event.target.value)} data-testid="attach-plant-kind">
            {plants.map((plant) => (
              <option key={plant.kind} value={plant.kind}>
                {t(`plants.kind.${plant.kind}`, { defaultValue: plant.title })}
              </option>
            ))}
          </select>
        </div>
        <p className="plant-attach__file">
          {t('plants.attach.file')} <bdi className="plant-attach__name">{name}</bdi>
        </p>
        {clash ? <p className="field__error" role="alert">{t('plants.attach.exists', { name })}</p> : null}
        {info ? (
          <table className="plant-wiring" data-testid="attach-plant-wiring">
            <caption>{t('plants.attach.wiring')}</caption>
            <thead>
              <tr>
                <th scope="col">{t('plants.attach.signal')}</th>
                <th scope="col">{t('plants.attach.direction')}</th>
                <th scope="col">{t('plants.attach.address')}</th>
              </tr>
            </thead>
            <tbody>
              {info.signals.map((signal) => {
                const problem = problems[signal.name];
                const errorId = `plant-wire-error-${signal.name}`;
                return (
                  <tr key={signal.name}>
                    <th scope="row">
                      {signalName(signal.name)} <code className="plant-wiring__id">{signal.name}</code>
                    </th>
                    <td>
                      {t(`plants.direction.${signal.direction}`)}
                      {signal.normally_closed ? ` · ${t('plants.attach.nc')}` : ''}
                      {signal.kind === 'word' ? ` · ${t('plants.attach.word')}` : ''}
                    </td>
                    <td>
                      <input
                        className="input plant-wiring__address"
                        dir="ltr"
                        value={wiring[signal.name] ?? ''}
                        placeholder={t('plants.attach.notWired')}
                        aria-label={t('plants.attach.addressOf', { name: signalName(signal.name) })}
                        aria-invalid={problem ? true : undefined}
                        aria-describedby={problem ? errorId : undefined}
                        data-testid={`attach-wire-${signal.name}`}
                        onChange={(event) => setWiring({ ...wiring, [signal.name]: event.target.value })}
                      />
                      {problem ? (
                        <span id={errorId} className="field__error" data-testid={`attach-wire-error-${signal.name}`}>
                          {problemText(problem)}
                        </span>
                      ) : null}
                    </td>
                  </tr>
                );
              })}
            </tbody>
          </table>
        ) : null}
        {info && Object.keys(info.defaults).length > 0 ? (
          <fieldset className="plant-params">
            <legend>{t('plants.attach.params')}</legend>
            {Object.keys(info.defaults).map((param) => (
              <label key={param} className="field plant-params__field">
                <code>{param}</code>
                <input
                  className="input"
                  inputMode="decimal"
                  dir="ltr"
                  value={params[param] ?? ''}
                  aria-invalid={badParams.includes(param) ? true : undefined}
                  data-testid={`attach-param-${param}`}
                  onChange={(event) => setParams({ ...params, [param]: event.target.value })}
                />
              </label>
            ))}
          </fieldset>
        ) : null}
        {error ? (
          <p className="field__error" role="alert" data-testid="attach-plant-error">
            {errorText(error)}
          </p>
        ) : null}
      </form>
    </Dialog>
  );
}
