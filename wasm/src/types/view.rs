//! TypeScript types: What a page draws: paths, chart views, specs and layouts.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TS_VIEW: &'static str = r#"
/** A path in metres. */
export interface Path {
  x_m: Float64Array;
  y_m: Float64Array;
}

/** Dead-reckoned paths of a drive with speed. */
export interface Tracks {
  raw: Path;
  hdr: Path;
  reference: Path | null;
}

/** Dead-reckoned paths along the recommended pipeline's causal and smoothed (offline) headings. */
export interface PipelineTracks {
  pipeline: Path;
  smoothed: Path;
}

/** What a page draws: a time window (null: all) and its width in pixel columns. Series
 * given to a view keep per column the first and last sample and each series' extremes. */
export interface ChartView {
  x_range?: [number, number] | null;
  columns: number;
}

/** A chart for drawChart: series are decimated to the canvas width in core. */
export interface ChartSpec {
  title?: string;
  x_label?: string;
  y_label?: string;
  x_range?: [number, number] | null;
  y_range?: [number, number] | null;
  log_x?: boolean;
  log_y?: boolean;
  /** x is time in seconds: drawn in s, min or h by the span shown, labelled "x_label (unit)". */
  time_x?: boolean;
  /** With time_x: the time the axis counts from, s (the log's first row, so that an
   * epoch-stamped log reads minutes since its start). Default 0. */
  x_origin?: number;
  /** Draw the legend inside the plot (default true). */
  legend?: boolean;
  /** Equal axes (a track in metres): one unit as long across as up; x_range and y_range are
   * ignored. The ranges fit the data with 5 % to spare, or follow `view`. */
  equal_axes?: boolean;
  /** With equal_axes: a zoomed or panned view, [x centre, y centre, units per canvas pixel]. */
  view?: [number, number, number] | null;
  series: { name: string; color: string; x: ArrayLike<number>; y: ArrayLike<number>; width?: number; points?: boolean; path?: boolean }[];
  shade?: { x: ArrayLike<number>; mask: ArrayLike<number>; color: string; label?: string } | null;
  cursor_x?: number | null;
  dpr?: number;
}

/** Where drawChart put the plot area (canvas pixels) and its data ranges. */
export interface ChartLayout {
  left: number;
  top: number;
  right: number;
  bottom: number;
  x_min: number;
  x_max: number;
  y_min: number;
  y_max: number;
  /** The time axis's unit ("s", "min", "h"), "" when x is not time. Ranges stay in seconds. */
  x_unit: string;
  /** Seconds in one x_unit (60 for "min"), 1 when x is not time. */
  x_unit_s: number;
  /** Where the time axis counts from, s (0 when x is not time): a time t reads
   * (t - x_origin) / x_unit_s. */
  x_origin: number;
  /** Where the ticks are, as labelled: round values (1, 2 or 5 times a power of ten apart)
   * in the axis's unit, whole decades on a log axis. */
  x_ticks: Float64Array;
  y_ticks: Float64Array;
}
"#;
