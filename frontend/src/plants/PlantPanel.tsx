import { useEffect, useState } from 'react';
import { useTranslation } from 'react-i18next';
import { ApiError, asApiError, deleteFile, getFile } from '../api/client';
import { useApiErrorText } from '../i18n/useApiErrorText';
import { useMonitor, useSession } from '../cpu/SessionContext';
import { useActiveProject } from '../projects/ActiveProject';
import { projectContents, useProjectContents } from '../projects/projectContents';
import { ConfirmDialog } from '../projects/TreeDialogs';
import { InfoIcon } from '../ui/icons';
import { usePlantCatalogue } from './api';
import { AttachPlantDialog } from './AttachPlantDialog';
import { OperatorPanel, plantCommandSender } from './OperatorPanel';
import { PlantDrawing, stillFrame } from './PlantDrawing';
import { PlantFileError, isPlantFile, readPlantFile } from './plantFile';
import type { PlantConfig } from './types';
import './plants.css';

type Loaded = {
  name: string;
  version: number;
  config: PlantConfig | null;
  /** Why the file cannot be shown: the line the browser cannot read, or the server's error. */
  error: { line: number } | ApiError | null;
};

/** The project's plant file as read from the server (null while there is none). */
function usePlantFile(projectId: number | null, name: string | null, version: number): Loaded | null {
  const [loaded, setLoaded] = useState<Loaded | null>(null);
  useEffect(() => {
    if (projectId === null || name === null) {
      setLoaded(null);
      return;
    }
    const request = new AbortController();
    getFile(projectId, name, request.signal).then(
      (file) => {
        try {
          setLoaded({ name, version, config: readPlantFile(file.text), error: null });
        } catch (error) {
          setLoaded({ name, version, config: null, error: { line: error instanceof PlantFileError ? error.line : 1 } });
        }
      },
      (error: unknown) => {
        if (!request.signal.aborted) setLoaded({ name, version, config: null, error: asApiError(error) });
      },
    );
    return () => request.abort();
  }, [projectId, name, version]);
  return loaded;
}

interface PlantPanelProps {
  /** The project whose plant is shown (default: the active project). */
  projectId?: number | null;
  /** Hides the attach / edit / detach buttons (a lesson's plant is the lesson's). */
  readOnly?: boolean;
}

/**
 * The virtual plant of a project: its drawing, animated from the session's frames while the
 * project's program runs, and its operator panel. A project attaches a plant with a
 * `<kind>.plant` file (one per project; the first one found counts, as the session does).
 * Before a session runs, the drawing shows the plant at rest with its wiring.
 */
export function PlantPanel({ projectId: given, readOnly = false }: PlantPanelProps) {
  const { t } = useTranslation();
  const errorText = useApiErrorText();
  const active = useActiveProject().projectId;
  const projectId = given === undefined ? active : given;
  const contents = useProjectContents(projectId);
  const plantFiles = (contents?.files ?? []).filter((file) => isPlantFile(file.name));
  const file = plantFiles[0] ?? null;
  const loaded = usePlantFile(projectId, file?.name ?? null, file?.version ?? 0);
  const { plants, status } = usePlantCatalogue();
  const { session, command } = useSession();
  const connection = useMonitor((state) => state.connection);
  const frame = useMonitor((state) => state.plant);
  const [dialog, setDialog] = useState<'attach' | 'edit' | 'detach' | null>(null);

  if (projectId === null) {
    return (
      <div className="plant-panel" data-testid="plant-panel">
        <p className="panel-empty">
          <InfoIcon className="panel-empty__icon" />
          {t('plants.noProject')}
        </p>
      </div>
    );
  }

  const ourSession = session !== null && session.projectId === projectId;
  const config = loaded?.config ?? null;
  const live = ourSession && frame !== null && file !== null && (config === null || frame.kind === config.kind);
  const kind = live ? frame.kind : config?.kind ?? null;
  const info = plants.find((plant) => plant.kind === kind);
  const shown = live ? frame : config ? stillFrame(config.kind, config.wiring, info) : null;
  const send = plantCommandSender(command);

  const toolbar = (
    <div className="plant-panel__toolbar">
      {file ? (
        <>
          <strong className="plant-panel__title" data-testid="plant-title">
            {kind ? t(`plants.kind.${kind}`, { defaultValue: info?.title ?? kind }) : file.name}
          </strong>
          <bdi className="plant-panel__file">{file.name}</bdi>
          {live ? null : <span className="plant-panel__hint" data-testid="plant-still">{t('plants.still')}</span>}
        </>
      ) : null}
      {readOnly ? null : (
        <span className="plant-panel__buttons">
          {file ? (
            <>
              <button type="button" className="button button--small" disabled={status !== 'ready' || !config} data-testid="plant-edit" onClick={() => setDialog('edit')}>
                {t('plants.edit')}
              </button>
              <button type="button" className="button button--small" data-testid="plant-detach" onClick={() => setDialog('detach')}>
                {t('plants.detach')}
              </button>
            </>
          ) : (
            <button type="button" className="button button--small button--primary" disabled={status !== 'ready'} data-testid="plant-attach" onClick={() => setDialog('attach')}>
              {t('plants.attachButton')}
            </button>
          )}
        </span>
      )}
    </div>
  );

  return (
    <div className="plant-panel" data-testid="plant-panel" data-live={live ? '1' : '0'}>
      {toolbar}
      {file === null ? (
        <p className="panel-empty">
          <InfoIcon className="panel-empty__icon" />
          {t('plants.none')}
        </p>
      ) : loaded?.error ? (
        <p className="field__error" role="alert" data-testid="plant-file-error">
          {loaded.error instanceof ApiError
            ? errorText(loaded.error)
            : t('plants.badFile', { name: file.name, line: loaded.error.line })}
        </p>
      ) : shown ? (
        <div className="plant-panel__body">
          <PlantDrawing plant={shown} info={info} params={config?.kind === shown.kind ? config.params : undefined} />
          <OperatorPanel plant={shown} info={info} disabled={!live || connection !== 'open'} send={send} />
        </div>
      ) : null}
      {dialog === 'attach' || dialog === 'edit' ? (
        <AttachPlantDialog
          projectId={projectId}
          files={contents?.files ?? []}
          plants={plants}
          editing={dialog === 'edit' && file && config ? { name: file.name, config } : null}
          onClose={() => setDialog(null)}
          onSaved={() => setDialog(null)}
        />
      ) : null}
      {dialog === 'detach' && file ? (
        <ConfirmDialog
          title={t('plants.detachTitle')}
          confirmLabel={t('plants.detach')}
          testId="plant-detach-dialog"
          onClose={() => setDialog(null)}
          onConfirm={async () => {
            await deleteFile(projectId, file.name);
            projectContents.removeFile(projectId, file.name);
            projectContents.reloadSoon(projectId);
            setDialog(null);
          }}
        >
          <p>{t('plants.detachText', { name: file.name })}</p>
        </ConfirmDialog>
      ) : null}
    </div>
  );
}
