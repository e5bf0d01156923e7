import { describe, expect, it } from 'vitest';
import { isRtl, lessonSegments, safeHtml, textLanguage } from '../../../frontend/src/lessons/markdown';
import { placeOfLine } from '../../../frontend/src/lad/reveal';

const figure = (name: string) => `/api/lessons/fa2-06/figures/${name}`;

function html(text: string): string {
  return lessonSegments(text, figure)
    .map((segment) => (segment.kind === 'html' ? segment.html : `[${segment.mode}]`))
    .join('');
}

describe('lesson text (Markdown made safe)', () => {
  it('removes scripts, event handlers, frames, forms and javascript: links', () => {
    const out = html(
      [
        '# Title',
        '',
        'Text <script>alert(1)</script> <img src="figures/a.svg" onerror="alert(2)">',
        '',
        '<iframe src="https://example.com"></iframe><form><input value="x"></form>',
        '',
        '[click](javascript:alert(3)) <a href="#" onclick="alert(4)">x</a>',
      ].join('\n'),
    );
    expect(out).not.toMatch(/script|onerror|onclick|iframe|<form|<input|javascript:/i);
    expect(out).toContain('Text');
  });

  it('serves figures from the lesson and never loads an image from elsewhere', () => {
    const out = html('![the tank](figures/tank.svg) ![remote](https://example.com/x.png) ![up](../other/x.svg) ![data](data:image/png;base64,AAAA)');
    expect(out).toContain('src="/api/lessons/fa2-06/figures/tank.svg"');
    expect(out).not.toContain('example.com');
    expect(out).not.toContain('../other');
    expect(out).not.toContain('data:image');
    // The captions of the dropped images stay as text.
    expect(out).toContain('remote');
    const doc = new DOMParser().parseFromString(out, 'text/html');
    expect(doc.querySelectorAll('img')).toHaveLength(1);
    expect(doc.querySelector('img')?.getAttribute('dir')).toBe('ltr');
  });

  it('keeps code blocks and inline addresses left to right inside right-to-left text', () => {
    const out = html('خروجی `Q 2.1` روشن می‌شود.\n\n```stl\nA OS\n= Q 2.1\n```\n');
    const doc = new DOMParser().parseFromString(out, 'text/html');
    expect(doc.querySelector('p code')?.getAttribute('dir')).toBe('ltr');
    expect(doc.querySelector('p code')?.textContent).toBe('Q 2.1');
    expect(doc.querySelector('pre')?.getAttribute('dir')).toBe('ltr');
    expect(doc.querySelector('pre code')?.textContent).toBe('A OS\n= Q 2.1\n');
  });

  it('cuts lad-view and fbd-view fences out as diagrams of their STL, in order, and drops the first title', () => {
    const segments = lessonSegments('# OS and BR\n\nBefore\n\n```lad-view\nA I 0.0\n= Q 4.0\n```\n\nBetween\n\n```fbd-view\nA I 0.1\n= Q 4.1\n```\n', figure);
    expect(segments.map((segment) => segment.kind)).toEqual(['html', 'diagram', 'html', 'diagram']);
    expect(segments[1]).toEqual({ kind: 'diagram', mode: 'LAD', stl: 'A I 0.0\n= Q 4.0' });
    expect(segments[3]).toEqual({ kind: 'diagram', mode: 'FBD', stl: 'A I 0.1\n= Q 4.1' });
    expect(html('# OS and BR\n\nBefore')).not.toContain('<h1');
    expect(html('Intro\n\n# Later heading')).toContain('<h1');
  });

  it('opens links to other sites in a new tab and turns paths into plain text', () => {
    const out = safeHtml('<p><a href="https://support.industry.siemens.com">manual</a> <a href="start/OB1.lad">file</a></p>', figure);
    expect(out).toContain('target="_blank"');
    expect(out).toContain('rel="noopener noreferrer"');
    expect(out).not.toContain('start/OB1.lad');
    expect(out).toContain('file');
  });
});

describe('the language a lesson is shown in', () => {
  it('is the interface language when the lesson has it, else English, else its own', () => {
    const texts = { fa: 'متن', en: 'text' };
    expect(textLanguage(['fa', 'en'], texts, 'fa')).toBe('fa');
    expect(textLanguage(['fa', 'en'], texts, 'vi')).toBe('en');
    expect(textLanguage(['fa'], { fa: 'متن' }, 'vi')).toBe('fa');
    expect(isRtl('fa')).toBe(true);
    expect(isRtl('ar')).toBe(true);
    expect(isRtl('vi')).toBe(false);
  });
});

describe('a place in a LAD file by line', () => {
  const text = [
    'ORGANIZATION_BLOCK OB 1', // 1
    'BEGIN', // 2
    'NETWORK', // 3
    'RUNG', // 4
    '  Contact(I 0.0)', // 5
    'END_RUNG', // 6
    'NETWORK', // 7
    'RUNG', // 8
    '  Coil(Q 2.1)', // 9
    'END_RUNG', // 10
    'END_ORGANIZATION_BLOCK', // 11
    'FUNCTION FC 1 : VOID', // 12
    'BEGIN', // 13
    'NETWORK', // 14
    'RUNG', // 15
    '  Coil(Q 4.0)', // 16
    'END_RUNG', // 17
    'END_FUNCTION', // 18
  ].join('\n');

  it('finds the block and the network whose NETWORK line comes last before the line', () => {
    expect(placeOfLine(text, 5)).toEqual({ block: 0, network: 0 });
    expect(placeOfLine(text, 9)).toEqual({ block: 0, network: 1 });
    expect(placeOfLine(text, 16)).toEqual({ block: 1, network: 0 });
  });

  it('takes a given network number (1-based) within the block of the line', () => {
    expect(placeOfLine(text, 1, 2)).toEqual({ block: 0, network: 1 });
    expect(placeOfLine(text, 13, 1)).toEqual({ block: 1, network: 0 });
  });
});
