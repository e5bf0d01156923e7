/**
 * What a new source opens with: small programs that compile with Nasaq's compilers as they
 * stand (`nasaq compile`). Kept apart from the language definitions, which load with Monaco.
 */

/** The comments of the two programs, in each interface language (the code is the same). */
interface ExampleComments {
  mainCycle: string;
  startInfo: string;
  motorTitle: string;
  startButton: string;
  selfHolding: string;
  stopButton: string;
  countStarts: string;
  tankTitle: string;
  levelSensor: string;
  fills: string;
}

const COMMENTS: Record<'en' | 'ar' | 'fa' | 'vi', ExampleComments> = {
  en: {
    mainCycle: 'Main cycle',
    startInfo: 'start information',
    motorTitle: 'Motor with a start and a stop button',
    startButton: 'start button',
    selfHolding: 'motor contactor holds itself',
    stopButton: 'stop button',
    countStarts: 'Count the starts',
    tankTitle: 'Tank filling',
    levelSensor: 'level sensor, 0..1000',
    fills: 'how often the pump started',
  },
  ar: {
    mainCycle: 'الدورة الرئيسية',
    startInfo: 'معلومات البدء',
    motorTitle: 'محرك بزر تشغيل وزر إيقاف',
    startButton: 'زر التشغيل',
    selfHolding: 'كونتاكتور المحرك يُمسك نفسه',
    stopButton: 'زر الإيقاف',
    countStarts: 'عدّ مرات التشغيل',
    tankTitle: 'تعبئة الخزان',
    levelSensor: 'حسّاس المنسوب، 0..1000',
    fills: 'كم مرة بدأت المضخة',
  },
  fa: {
    mainCycle: 'چرخهٔ اصلی',
    startInfo: 'اطلاعات شروع',
    motorTitle: 'موتور با یک شستی راه‌اندازی و یک شستی توقف',
    startButton: 'شستی راه‌اندازی',
    selfHolding: 'کنتاکتور موتور خودش را نگه می‌دارد',
    stopButton: 'شستی توقف',
    countStarts: 'شمردن راه‌اندازی‌ها',
    tankTitle: 'پر کردن مخزن',
    levelSensor: 'حسگر سطح، 0..1000',
    fills: 'چند بار پمپ روشن شده است',
  },
  vi: {
    mainCycle: 'Chu kỳ chính',
    startInfo: 'thông tin khởi động',
    motorTitle: 'Động cơ với nút chạy và nút dừng',
    startButton: 'nút chạy',
    selfHolding: 'công tắc tơ động cơ tự duy trì',
    stopButton: 'nút dừng',
    countStarts: 'Đếm số lần khởi động',
    tankTitle: 'Cấp nước vào bồn',
    levelSensor: 'cảm biến mức, 0..1000',
    fills: 'số lần bơm đã khởi động',
  },
};

function stlExample(c: ExampleComments): string {
  return `ORGANIZATION_BLOCK OB 1
TITLE = ${c.mainCycle}
VERSION : 0.1

VAR_TEMP
  info : ARRAY [0 .. 19] OF BYTE;   // ${c.startInfo}
END_VAR

BEGIN
NETWORK
TITLE = ${c.motorTitle}
      A(    ;
      O     I      0.0;             // ${c.startButton}
      O     Q      4.0;             // ${c.selfHolding}
      )     ;
      AN    I      0.1;             // ${c.stopButton}
      =     Q      4.0;

NETWORK
TITLE = ${c.countStarts}
      A     I      0.0;
      FP    M     10.0;
      JCN   M001;
      L     MW    20;
      +     1;
      T     MW    20;
M001: NOP   0;
END_ORGANIZATION_BLOCK
`;
}

function sclExample(c: ExampleComments): string {
  return `FUNCTION_BLOCK FB 10
TITLE = '${c.tankTitle}'
VERSION : '0.1'

VAR_INPUT
  level : INT;            // ${c.levelSensor}
  low : INT := 200;
  high : INT := 800;
END_VAR
VAR_OUTPUT
  pump : BOOL;
END_VAR
VAR
  fills : DINT;           (* ${c.fills} *)
END_VAR

BEGIN
  IF level < low AND NOT pump THEN
    pump := TRUE;
    fills := fills + 1;
  ELSIF level >= high THEN
    pump := FALSE;
  END_IF;
  MW20 := INT_TO_WORD(level);
  Q4.0 := pump;
END_FUNCTION_BLOCK
`;
}

/** A small program for a new STL source: a self-holding motor circuit in OB1. */
export const STL_EXAMPLE = stlExample(COMMENTS.en);

/** A small program for a new SCL source: a tank filled between two levels. */
export const SCL_EXAMPLE = sclExample(COMMENTS.en);

/**
 * The program a new source opens with, commented in `language` (by default the page's: a
 * Persian student's first program explains itself in Persian); the code is the same in all.
 */
export function sourceExample(kind: 'stl' | 'scl', language: string = pageLanguage()): string {
  const comments = COMMENTS[language as keyof typeof COMMENTS] ?? COMMENTS.en;
  return kind === 'stl' ? stlExample(comments) : sclExample(comments);
}

function pageLanguage(): string {
  return typeof document === 'undefined' ? 'en' : document.documentElement.lang;
}
