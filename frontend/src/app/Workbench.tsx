import { useCallback, useRef } from 'react';
import { EditorArea } from '../editor/EditorArea';
import { useDocumentLanguage } from '../i18n/useDocumentLanguage';
import { LessonPane } from '../lessons/LessonPane';
import { BottomPanel } from '../panels/BottomPanel';
import { SessionProvider } from '../cpu/SessionContext';
import { ActiveProjectProvider } from '../projects/ActiveProject';
import { ProjectTree } from '../projects/ProjectTree';
import { usePersistentFlag } from '../ui/usePersistentState';
import { CompileProvider } from './compile';
import { StatusBar } from './StatusBar';
import { TopBar } from './TopBar';

/** Where the lesson pane's open/closed state is remembered. */
export const LESSON_PANE_STORAGE_KEY = 'nasaq.lessonPane.open';

/**
 * The IDE layout: top bar; project tree | editor over the bottom panel | lesson pane;
 * status bar. The grid mirrors by itself in right-to-left languages.
 */
export function Workbench() {
  useDocumentLanguage();
  const [lessonsOpen, setLessonsOpen] = usePersistentFlag(LESSON_PANE_STORAGE_KEY, true);
  const lessonToggle = useRef<HTMLButtonElement>(null);

  const closeLessons = useCallback(() => {
    setLessonsOpen(false);
    lessonToggle.current?.focus();
  }, [setLessonsOpen]);

  return (
    <ActiveProjectProvider>
      <SessionProvider>
        <CompileProvider>
          <div className={lessonsOpen ? 'workbench workbench--lessons' : 'workbench'}>
            <TopBar
              lessonPaneOpen={lessonsOpen}
              onToggleLessonPane={() => setLessonsOpen(!lessonsOpen)}
              lessonToggleRef={lessonToggle}
            />
            <div className="workbench__body">
              <ProjectTree />
              <main className="workbench__main">
                <EditorArea />
                <BottomPanel />
              </main>
              {lessonsOpen ? <LessonPane onClose={closeLessons} /> : null}
            </div>
            <StatusBar />
          </div>
        </CompileProvider>
      </SessionProvider>
    </ActiveProjectProvider>
  );
}
