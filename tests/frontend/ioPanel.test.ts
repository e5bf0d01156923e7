/** The I/O panel's logic: which bytes and analog words the program uses, S7 analog ranges and scaling, words typed by the user, and the slider's sender. */
import fs from 'node:fs';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import { findScale, parseWord, percentOf, regionOf, scaled, sliderRange } from '../../frontend/src/io/analog';
import { ioUsage, shownBytes } from '../../frontend/src/io/ioUsage';
import { LatestOnly } from '../../frontend/src/io/latestOnly';

const examples = path.resolve(__dirname, '../../examples/projects');
const project = (name: string) =>
  fs
    .readdirSync(path.join(examples, name))
    .filter((file) => !file.endsWith('.yaml') && fs.statSync(path.join(examples, name, file)).isFile())
    .map((file) => ({ name: file, text: fs.readFileSync(path.join(examples, name, file), 'utf8') }));

describe('I/O the program uses', () => {
  it('finds the digital bytes and the analog words of the examples', () => {
    expect(ioUsage(project('motor-start-stop'))).toEqual({ inputs: [0], outputs: [4], analogInputs: [], analogOutputs: [] });
    expect(ioUsage(project('tank-level'))).toEqual({
      inputs: [0],
      outputs: [4],
      analogInputs: [{ address: 'IW64', byte: 64, peripheral: false }],
      analogOutputs: [],
    });
  });

  it('reads either mnemonic set, LAD/FBD and SCL, and never a label or an AND', () => {
    const german = { name: 'FC1.awl', text: 'U E 6.1\n= A 5.0\nL PEW 256\nT PAW 272\nL AW 8\nA I 0.0\nE001: NOP 0' };
    expect(ioUsage([german])).toEqual({
      inputs: [0, 6],
      outputs: [5],
      analogInputs: [{ address: 'PIW256', byte: 256, peripheral: true }],
      analogOutputs: [
        { address: 'QW8', byte: 8, peripheral: false },
        { address: 'PQW272', byte: 272, peripheral: true },
      ],
    });
    expect(ioUsage([{ name: 'FC2.scl', text: '%Q7.1 := %I12.0 AND x; y := 1.5E 3;' }])).toMatchObject({ inputs: [12], outputs: [7] });
    const ladder = 'RUNG\n  Contact(I 3.0)\n  ContactNC("Stop")\n  Coil(Q 6.1)\nEND_RUNG';
    expect(ioUsage([{ name: 'Latch.lad', text: ladder }])).toMatchObject({ inputs: [3], outputs: [6] });
    expect(ioUsage([{ name: 'Gates.fbd', text: ladder }])).toMatchObject({ inputs: [3], outputs: [6] });
  });

  it('takes a word whose bytes are also used bit by bit as digital, and double words as bytes', () => {
    const text = 'A I 1.3\nL IW 0\nT QD 4\nL PIW 64\nL IW 64\n';
    const usage = ioUsage([{ name: 'OB1.awl', text }]);
    expect(usage.inputs).toEqual([0, 1]);
    expect(usage.outputs).toEqual([4, 5, 6, 7]);
    // Used through the process image somewhere: named IW64, not PIW64.
    expect(usage.analogInputs).toEqual([{ address: 'IW64', byte: 64, peripheral: false }]);
  });

  it('shows the used bytes by default and every byte from 0 on request', () => {
    expect(shownBytes([4], false)).toEqual([4]);
    expect(shownBytes([4], true)).toEqual([0, 1, 2, 3, 4]);
    expect(shownBytes([], true)).toEqual([0, 1, 2, 3]);
    expect(shownBytes([], false)).toEqual([]);
  });
});

describe('S7 analog values', () => {
  it('classifies raw values as the S7-300 module data manual does', () => {
    const unipolar = [32767, 32511, 27649, 27648, 0, -1, -4864, -4865].map((raw) => regionOf(raw, false));
    expect(unipolar).toEqual(['overflow', 'overrange', 'overrange', 'nominal', 'nominal', 'underrange', 'underrange', 'underflow']);
    const bipolar = [27648, -27648, -27649, -32512, -32768].map((raw) => regionOf(raw, true));
    expect(bipolar).toEqual(['nominal', 'nominal', 'underrange', 'underrange', 'underflow']);
    expect(sliderRange(false)).toEqual({ min: -4864, max: 32511 });
    expect(sliderRange(true)).toEqual({ min: -32512, max: 32511 });
    expect(percentOf(13824)).toBe(50);
  });

  it('scales with FC105 SCALE\'s formula, unipolar and bipolar', () => {
    const scale = { block: 'FC105', low: 0, high: 100, bipolar: false, target: null };
    expect(scaled(27648, scale)).toBe(100);
    expect(scaled(2765, scale)).toBeCloseTo(10.0, 2);
    expect(scaled(0, { ...scale, bipolar: true })).toBe(50);
    expect(scaled(-27648, { ...scale, low: -10, high: 10, bipolar: true })).toBe(-10);
  });

  it("finds the tank example's scaling function and an FC105 call with its limits", () => {
    expect(findScale(project('tank-level'), ['IW64', '"Level sensor"'])).toEqual({
      block: '"Scale"',
      low: 0,
      high: 100,
      bipolar: false,
      target: '"Level"',
    });
    const fc105 = 'CALL FC 105 (\n IN := PIW 256,\n HI_LIM := 1.0e3,\n LO_LIM := -2.5e2,\n BIPOLAR := TRUE,\n RET_VAL := MW 20,\n OUT := MD 30);';
    expect(findScale([{ name: 'OB1.awl', text: fc105 }], ['PIW256'])).toEqual({
      block: 'FC105',
      low: -250,
      high: 1000,
      bipolar: true,
      target: 'MD 30',
    });
    // SCL, an UNSCALE of an output: the word is the OUT parameter.
    const scl = 'ret := UNSCALE(IN := speed, HI_LIM := 1500.0, LO_LIM := 0.0, BIPOLAR := FALSE, OUT => %QW80);';
    expect(findScale([{ name: 'FC3.scl', text: scl }], ['QW80'])).toMatchObject({ block: 'UNSCALE', low: 0, high: 1500, target: 'speed' });
    // Limits in variables are not known before the program runs.
    const variable = 'CALL FC 105 (IN := IW 66, HI_LIM := #hi, LO_LIM := 0.0, BIPOLAR := FALSE, RET_VAL := MW 2, OUT := MD 4);';
    expect(findScale([{ name: 'OB1.awl', text: variable }], ['IW66'])).toBeNull();
    expect(findScale(project('tank-level'), ['IW70'])).toBeNull();
  });

  it('reads a word typed in decimal, hex or binary, and refuses what is not one', () => {
    expect(['13824', '-100', '16#6C00', 'W#16#FFFF', '2#0000_0001', ' 32767 '].map(parseWord)).toEqual([
      13824, -100, 27648, -1, 1, 32767,
    ]);
    expect(['', 'abc', '32768', '-32769', '1.5', '16#10000'].map(parseWord)).toEqual([null, null, null, null, null, null]);
  });
});

describe('the slider sender', () => {
  it('sends one value at a time and, of those that came meanwhile, only the last', async () => {
    const sent: number[] = [];
    const answers: Array<() => void> = [];
    const sender = new LatestOnly<number>(
      (value) =>
        new Promise<void>((resolve) => {
          sent.push(value);
          answers.push(resolve);
        }),
    );
    sender.push(1);
    sender.push(2);
    sender.push(3);
    expect(sent).toEqual([1]);
    answers.shift()!();
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(sent).toEqual([1, 3]);
    answers.shift()!();
    await new Promise((resolve) => setTimeout(resolve, 0));
    sender.push(4);
    expect(sent).toEqual([1, 3, 4]);
  });
});
