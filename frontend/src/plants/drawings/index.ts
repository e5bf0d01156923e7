/** One drawing per plant kind (backend/nasaq/plants/<kind>.py); a kind without one gets the generic drawing. */
import type { ComponentType } from 'react';
import type { DrawingProps } from '../parts';
import { BcdPanelDrawing } from './BcdPanelDrawing';
import { BottleConveyorDrawing } from './BottleConveyorDrawing';
import { CarParkDrawing } from './CarParkDrawing';
import { DrillDrawing } from './DrillDrawing';
import { CylinderDrawing, CylindersDrawing, DoorDrawing, HopperDrawing, ServoPistonDrawing, ShuttleDrawing } from './LinearDrawings';
import { CutterDrawing, PackagingLineDrawing, RollerCoasterDrawing, ShrinkWrapDrawing, SorterDrawing, YoghurtFillerDrawing } from './LineDrawings';
import { MixerDrawing } from './MixerDrawing';
import { MotorDrawing } from './MotorDrawing';
import { PanelDrawing } from './PanelDrawing';
import { TankDrawing } from './TankDrawing';
import { TrafficLightDrawing } from './TrafficLightDrawing';

export const DRAWINGS: Readonly<Record<string, ComponentType<DrawingProps>>> = {
  tank: TankDrawing,
  motor: MotorDrawing,
  bottle_conveyor: BottleConveyorDrawing,
  traffic_light: TrafficLightDrawing,
  car_park: CarParkDrawing,
  drill: DrillDrawing,
  mixer: MixerDrawing,
  panel: PanelDrawing,
  bcd_panel: BcdPanelDrawing,
  door: DoorDrawing,
  shuttle: ShuttleDrawing,
  cylinder: CylinderDrawing,
  packaging_line: PackagingLineDrawing,
  hopper: HopperDrawing,
  sorter: SorterDrawing,
  yoghurt_filler: YoghurtFillerDrawing,
  roller_coaster: RollerCoasterDrawing,
  cutter: CutterDrawing,
  servo_piston: ServoPistonDrawing,
  shrink_wrap: ShrinkWrapDrawing,
  cylinders: CylindersDrawing,
};
