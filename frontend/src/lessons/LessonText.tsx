import { useMemo } from 'react';
import { figureUrl } from './api';
import { LessonDiagram } from './LessonDiagram';
import { isRtl, lessonSegments } from './markdown';

/**
 * A lesson's text in one language: its Markdown made safe (see markdown.ts) with the STL of
 * its `lad-view`/`fbd-view` fences drawn as diagrams. Arabic and Persian text runs right to
 * left; code, addresses, figures and diagrams stay left to right.
 */
export function LessonText({ lessonId, language, text }: { lessonId: string; language: string; text: string }) {
  const segments = useMemo(() => lessonSegments(text, (name) => figureUrl(lessonId, name)), [lessonId, text]);
  return (
    <div className="lesson-text" dir={isRtl(language) ? 'rtl' : 'ltr'} lang={language} data-testid="lesson-text">
      {segments.map((segment, k) =>
        segment.kind === 'html' ? (
          // Sanitized by DOMPurify in lessonSegments.
          <div key={k} className="lesson-text__html" dangerouslySetInnerHTML={{ __html: segment.html }} />
        ) : (
          <LessonDiagram key={k} stl={segment.stl} mode={segment.mode} />
        ),
      )}
    </div>
  );
}
