/**
 * The planned course, unit by unit, with the languages of the source material each
 * unit is built from. The lesson texts themselves arrive in a later release.
 */
export interface CourseUnit {
  id: string;
  /** Languages whose course files the unit draws on (besides English). */
  sources: ReadonlyArray<'ar' | 'fa' | 'vi'>;
}

export const COURSE_OUTLINE: readonly CourseUnit[] = [
  { id: 'addresses', sources: ['vi'] },
  { id: 'bitLogic', sources: ['ar', 'vi'] },
  { id: 'timersCounters', sources: ['ar', 'vi'] },
  { id: 'dataMath', sources: ['fa', 'vi'] },
  { id: 'blocks', sources: ['fa', 'vi'] },
  { id: 'scl', sources: ['fa'] },
  { id: 'graph', sources: ['ar', 'fa'] },
];
