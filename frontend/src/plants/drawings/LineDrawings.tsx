import { useTranslation } from 'react-i18next';
import { Belt, Caption, FaultMark, Lamp, Motor, PhotoEye, PlantSvg, SignalLabel, bit, clamp01, hasFault, param, stateNumber, type DrawingProps } from '../parts';

/** P05: boxes on one conveyor, pieces dropped into them from a second one. */
export function PackagingLineDrawing({ plant, params }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const scale = 0.4; // px per mm
  const landing = 250; // where pieces drop, in the drawing
  const pitch = param(params, 'box_pitch', 400);
  const boxLength = param(params, 'box_length', 200);
  const front = stateNumber(plant, ['box_position'], 0);
  const boxes: number[] = [];
  for (let k = -2; k <= 2; k += 1) {
    const x = landing + (front - k * pitch) * scale;
    if (x > 20 && x - boxLength * scale < 440) boxes.push(x);
  }
  return (
    <PlantSvg width={460} height={230} plant={plant}>
      <Belt x={20} y={80} width={230} running={bit(plant, 'piece_conveyor')} timeMs={time} testId="plant-belt-piece" />
      <SignalLabel plant={plant} name="piece_conveyor" x={20} y={105} at="right" />
      {stateNumber(plant, ['piece_falling']) ? <rect x={landing - 6} y={120} width={12} height={12} className="plant-piece" data-testid="plant-piece-falling" /> : null}
      <Belt x={20} y={190} width={420} running={bit(plant, 'box_conveyor')} timeMs={time} testId="plant-belt-box" />
      <SignalLabel plant={plant} name="box_conveyor" x={20} y={215} at="right" />
      {boxes.map((x, index) => (
        <rect key={index} x={Math.max(20, x - boxLength * scale)} y={160} width={Math.min(440, x) - Math.max(20, x - boxLength * scale)} height={30} className="plant-box" data-testid="plant-box" />
      ))}
      <PhotoEye plant={plant} name="piece_eye" x={235} y1={55} y2={72} />
      <PhotoEye plant={plant} name="box_eye" x={landing + 40} y1={130} y2={182} />
      {hasFault(plant, 'spill') ? <FaultMark x={landing} y={150} /> : null}
      <Caption x={330} y={30} anchor="start" testId="plant-count">{t('plants.boxes', { pieces: stateNumber(plant, ['box_pieces']), full: stateNumber(plant, ['boxes_full']) })}</Caption>
    </PlantSvg>
  );
}

/** P18: a sorting conveyor: colour and height eyes, a gate and a pusher, an exit eye. */
export function SorterDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const gate = clamp01(stateNumber(plant, ['gate']) / 100);
  const pusher = clamp01(stateNumber(plant, ['pusher']) / 100);
  return (
    <PlantSvg width={460} height={220} plant={plant}>
      <Belt x={20} y={150} width={420} running={bit(plant, 'conveyor')} timeMs={time} testId="plant-belt" />
      <SignalLabel plant={plant} name="conveyor" x={20} y={175} at="right" />
      <PhotoEye plant={plant} name="green_eye" x={60} y1={100} y2={142} />
      <PhotoEye plant={plant} name="red_eye" x={120} y1={100} y2={142} />
      <PhotoEye plant={plant} name="high_eye" x={180} y1={100} y2={142} />
      <PhotoEye plant={plant} name="low_eye" x={240} y1={100} y2={142} />
      <PhotoEye plant={plant} name="exit_eye" x={420} y1={100} y2={142} />
      <g transform={`rotate(${-60 * gate} 330 150)`} data-testid="plant-gate" data-position={gate.toFixed(2)}>
        <rect x={330} y={146} width={50} height={6} className="plant-barrier" />
      </g>
      <rect x={280} y={190 - 30 * pusher} width={14} height={14} className="plant-actuator" data-testid="plant-pusher" />
      <Lamp plant={plant} name="gate" x={340} y={200} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="pusher" x={200} y={200} colour="blue" r={6} label="right" />
      {hasFault(plant, 'missorted') ? <FaultMark x={380} y={130} /> : null}
      <Caption x={20} y={30} anchor="start" testId="plant-count">{t('plants.sorted', { good: stateNumber(plant, ['good']), bad: stateNumber(plant, ['missorted']) })}</Caption>
    </PlantSvg>
  );
}

/** P19: cups on a conveyor under a yoghurt piston (solenoid A) with cup, full and piston sensors. */
export function YoghurtFillerDrawing({ plant, params }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const nozzle = 220;
  const scale = 0.8;
  const pitch = param(params, 'pitch', 200);
  const cupX = stateNumber(plant, ['cup_position'], -pitch / 2);
  const fill = Math.max(0, stateNumber(plant, ['fill'])) / 100;
  const piston = clamp01(stateNumber(plant, ['piston']) / 100);
  const cups: Array<[number, number]> = [];
  for (let k = -2; k <= 2; k += 1) {
    const x = nozzle + (cupX + k * pitch) * scale;
    if (x > 30 && x < 430) cups.push([x, k === 0 ? fill : 0]);
  }
  return (
    <PlantSvg width={460} height={220} plant={plant}>
      <Belt x={20} y={170} width={420} running={bit(plant, 'conveyor')} timeMs={time} testId="plant-belt" />
      <SignalLabel plant={plant} name="conveyor" x={20} y={195} at="right" />
      {cups.map(([x, amount], index) => (
        <g key={index} data-testid="plant-cup" data-fill={(amount * 100).toFixed(0)}>
          <rect x={x - 10} y={170 - 26 * Math.min(1, amount)} width={20} height={26 * Math.min(1, amount)} className={amount > 1.1 ? 'plant-water--over' : 'plant-yoghurt'} />
          <path d={`M ${x - 12} 142 L ${x - 9} 170 L ${x + 9} 170 L ${x + 12} 142`} className="plant-bottle__glass" />
        </g>
      ))}
      <path d={`M ${nozzle - 30} 30 L ${nozzle + 30} 30 L ${nozzle + 8} 90 L ${nozzle - 8} 90 Z`} className="plant-cylinder" />
      <rect x={nozzle - 10 + piston * 22} y={90} width={20} height={6} className="plant-piston" data-testid="plant-piston" data-position={piston.toFixed(2)} />
      <Lamp plant={plant} name="sol_a" x={290} y={40} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="piston_left" x={290} y={80} colour="yellow" r={6} label="right" />
      <PhotoEye plant={plant} name="cup" x={nozzle - 70} y1={120} y2={162} />
      <PhotoEye plant={plant} name="full" x={nozzle + 60} y1={120} y2={140} />
      <Caption x={20} y={30} anchor="start" testId="plant-count">{t('plants.cups', { good: stateNumber(plant, ['cups_good']), bad: stateNumber(plant, ['cups_bad']) })}</Caption>
    </PlantSvg>
  );
}

/** P20: three conveyors and a shrink tunnel with its heater and temperature. */
export function ShrinkWrapDrawing({ plant }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const hot = bit(plant, 'tunnel_hot');
  return (
    <PlantSvg width={460} height={220} plant={plant}>
      <Belt x={10} y={150} width={130} running={bit(plant, 'conveyor_a')} timeMs={time} testId="plant-belt-a" />
      <Belt x={160} y={150} width={140} running={bit(plant, 'conveyor_b')} timeMs={time} testId="plant-belt-b" />
      <Belt x={320} y={150} width={130} running={bit(plant, 'conveyor_c')} timeMs={time} testId="plant-belt-c" />
      <SignalLabel plant={plant} name="conveyor_a" x={75} y={175} />
      <SignalLabel plant={plant} name="conveyor_b" x={230} y={175} />
      <SignalLabel plant={plant} name="conveyor_c" x={385} y={175} />
      <path d="M 170 150 L 170 80 Q 230 50 290 80 L 290 150" className={hot ? 'plant-tunnel plant-tunnel--hot' : 'plant-tunnel'} data-testid="plant-tunnel" />
      <Caption x={230} y={115} strong testId="plant-temperature">{`${stateNumber(plant, ['temperature']).toFixed(0)} °C`}</Caption>
      <Lamp plant={plant} name="heater" x={230} y={35} colour="red" r={7} label="right" />
      <Lamp plant={plant} name="tunnel_hot" x={340} y={35} colour="yellow" r={6} label="right" />
      <PhotoEye plant={plant} name="eye_a" x={130} y1={110} y2={142} />
      <PhotoEye plant={plant} name="eye_b" x={300} y1={110} y2={142} />
      <PhotoEye plant={plant} name="eye_c" x={440} y1={110} y2={142} />
      <Caption x={20} y={30} anchor="start" testId="plant-count">{t('plants.packs', { good: stateNumber(plant, ['packs_good']), line: stateNumber(plant, ['packs_on_line']) })}</Caption>
    </PlantSvg>
  );
}

/** P10: a bar fed by a wheel to a length eye, stopped by a brake, cut by a knife. */
export function CutterDrawing({ plant, params }: DrawingProps) {
  const { t } = useTranslation();
  const time = plant.time_ms;
  const knife = 160;
  const length = param(params, 'length', 500);
  const eye = 420;
  const scale = (eye - knife) / length;
  const bar = Math.max(0, stateNumber(plant, ['bar_position']));
  const knifeDown = clamp01(stateNumber(plant, ['knife_position']) / 100);
  return (
    <PlantSvg width={460} height={210} plant={plant}>
      <rect x={20} y={110} width={knife - 20 + Math.min(bar * scale, 450 - knife)} height={14} className="plant-material" data-testid="plant-material" />
      <Motor x={70} y={90} r={16} running={bit(plant, 'wheel')} timeMs={time} testId="plant-wheel" />
      <SignalLabel plant={plant} name="wheel" x={70} y={90} r={16} at="above" />
      <Lamp plant={plant} name="brake" x={110} y={150} colour="red" r={6} label="right" />
      <rect x={knife - 6} y={50 + knifeDown * 60} width={12} height={40} className="plant-knife" data-testid="plant-knife" />
      <Lamp plant={plant} name="knife" x={200} y={40} colour="blue" r={6} label="right" />
      <Lamp plant={plant} name="knife_home" x={200} y={70} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="cut_done" x={200} y={170} colour="yellow" r={6} label="right" />
      <PhotoEye plant={plant} name="dimension_eye" x={eye} y1={80} y2={130} />
      {hasFault(plant, 'wrong_length') ? <FaultMark x={eye} y={117} /> : null}
      <Caption x={300} y={190} anchor="start" testId="plant-count">{t('plants.pieces', { value: stateNumber(plant, ['pieces']), wrong: stateNumber(plant, ['wrong_pieces']) })}</Caption>
    </PlantSvg>
  );
}

/** P13: a roller coaster train that waits in the station; the siren must sound 15 s before it leaves. */
export function RollerCoasterDrawing({ plant, params }: DrawingProps) {
  const { t } = useTranslation();
  const track = param(params, 'track_m', 400);
  const position = (stateNumber(plant, ['position']) / track) % 1;
  const angle = Math.PI * 2 * position;
  const tx = 230 + Math.cos(angle + Math.PI / 2) * 170;
  const ty = 110 + Math.sin(angle + Math.PI / 2) * 70;
  return (
    <PlantSvg width={460} height={230} plant={plant}>
      <ellipse cx={230} cy={110} rx={170} ry={70} className="plant-rail" />
      <rect x={200} y={170} width={60} height={24} className="plant-station" />
      <rect x={tx - 18} y={ty - 9} width={36} height={18} rx={5} className="plant-car" data-testid="plant-train" data-position={position.toFixed(3)} />
      <Lamp plant={plant} name="station" x={300} y={200} colour="yellow" r={6} label="right" />
      <Lamp plant={plant} name="drive" x={40} y={30} colour="blue" r={7} label="right" />
      <Lamp plant={plant} name="siren" x={360} y={30} colour="red" r={7} label="right" />
      <Caption x={230} y={115} testId="plant-laps">{t('plants.laps', { value: stateNumber(plant, ['laps']) })}</Caption>
    </PlantSvg>
  );
}
