import { useTranslation } from 'react-i18next';
import { PlantPanel } from '../plants/PlantPanel';
import type { PlantConfig } from '../plants/types';

/**
 * The lesson's virtual plant, beside its text: the plant panel of the workbench (drawing,
 * animation from the session's frames, operator panel) on the lesson's project, whose
 * `<kind>.plant` file the lesson wrote. Read-only here: the plant belongs to the lesson.
 */
export function LessonPlant({ config, projectId }: { config: PlantConfig; projectId: number }) {
  const { t } = useTranslation();
  return (
    <section className="lesson-plant" aria-label={t('lessonPane.plant.title')} data-testid="lesson-plant" data-kind={config.kind}>
      <h4 className="lesson-section-title">{t('lessonPane.plant.title')}</h4>
      <p className="lesson-pane__note">{t('lessonPane.plant.text')}</p>
      <PlantPanel projectId={projectId} readOnly />
    </section>
  );
}
