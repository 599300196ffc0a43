//! Figures: panels of lines, points, reference lines and instants on linear axes, rendered to SVG by
//! [`svg`] (our own small writer: no dependency, the same bytes on every run) and to PNG by [`png`].
//!
//! Every figure can be read back: each panel carries its data range and its pixel box as `data-*`
//! attributes and each series its label, so a test (or a user's script) can turn pixels back into data.

pub mod analyses;
pub mod axis;
pub mod figures;
pub mod font;
#[cfg(feature = "png")]
pub mod png;
pub mod svg;

pub use axis::Quantity;

/// Colour-blind-safe colours (Okabe & Ito 2008), then neutral dark grey; cycled for many series.
pub const PALETTE: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#8C6D31",
];

/// Marker shapes of points, cycled with the palette so that a contact level keeps one colour and one shape
/// in every figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A disc.
    Circle,
    /// A square.
    Square,
    /// A triangle pointing up.
    Triangle,
    /// A diamond.
    Diamond,
    /// A triangle pointing down.
    TriangleDown,
    /// A hexagon.
    Hexagon,
}

/// The shapes in the order levels take them.
pub const SHAPES: [Shape; 6] = [
    Shape::Circle,
    Shape::Square,
    Shape::Triangle,
    Shape::Diamond,
    Shape::TriangleDown,
    Shape::Hexagon,
];

/// Line dash patterns, cycled after the palette so that 24 series stay distinct.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dash {
    /// Continuous.
    Solid,
    /// Long dashes.
    Dashed,
    /// Dots.
    Dotted,
}

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Style {
    /// CSS colour.
    pub color: &'static str,
    /// Dash pattern.
    pub dash: Dash,
    /// Line width (or point radius), px.
    pub width: f64,
    /// A line also marks each of its points with a dot (short lines: profiles over floors).
    pub marker: bool,
    /// Shape of points (and of a line's markers).
    pub shape: Shape,
}

impl Style {
    /// The `i`-th style of the cycle: palette colours first, then the same colours dashed, then dotted.
    pub fn nth(i: usize) -> Self {
        let dash = match (i / PALETTE.len()) % 3 {
            0 => Dash::Solid,
            1 => Dash::Dashed,
            _ => Dash::Dotted,
        };
        Self {
            color: PALETTE[i % PALETTE.len()],
            dash,
            width: 1.6,
            marker: false,
            shape: Shape::Circle,
        }
    }

    /// The style of contact level `k` (a contact element or a wall's floor, counted over the figure): the
    /// `k`-th palette colour and the `k`-th shape, so that 48 levels stay distinct and a level's line,
    /// markers and restitution points match.
    pub fn level(k: usize) -> Self {
        Self {
            color: PALETTE[k % PALETTE.len()],
            dash: Dash::Solid,
            width: 1.4,
            marker: false,
            shape: SHAPES[k % SHAPES.len()],
        }
    }

    /// A thin dashed grey line for references (ideal line, gap).
    pub fn reference() -> Self {
        Self {
            color: "#555555",
            dash: Dash::Dashed,
            width: 1.2,
            marker: false,
            shape: Shape::Circle,
        }
    }
}

/// What a series draws.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// A polyline through the points (x, y), SI units.
    Line {
        /// Abscissae.
        x: Vec<f64>,
        /// Ordinates.
        y: Vec<f64>,
    },
    /// Separate points (x, y), SI units.
    Points {
        /// Abscissae.
        x: Vec<f64>,
        /// Ordinates.
        y: Vec<f64>,
    },
    /// A horizontal line across the panel at y, SI units.
    HLine(f64),
    /// Instants on the x axis, drawn as short ticks along the top of the panel.
    Rug(Vec<f64>),
}

/// One labelled series of a panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend text (empty: not in the legend).
    pub label: String,
    /// What is drawn.
    pub mark: Mark,
    /// How it is drawn.
    pub style: Style,
}

impl Series {
    /// A line through `(x, y)`.
    pub fn line(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, style: Style) -> Self {
        Self {
            label: label.into(),
            mark: Mark::Line { x, y },
            style,
        }
    }

    /// Points at `(x, y)`.
    pub fn points(label: impl Into<String>, x: Vec<f64>, y: Vec<f64>, style: Style) -> Self {
        Self {
            label: label.into(),
            mark: Mark::Points { x, y },
            style,
        }
    }
}

/// Where a panel's legend goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Legend {
    /// Inside the plot, in the corner that hides the fewest data points.
    Inside,
    /// To the right of the plot (for long lists).
    Right,
    /// No legend.
    None,
}

/// One plot: axes, series and legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    /// Title above the plot.
    pub title: String,
    /// Quantity on the x axis.
    pub x: Quantity,
    /// Quantity on the y axis.
    pub y: Quantity,
    /// Keep the x axis at the data range (time axes) instead of rounding to ticks.
    pub x_tight: bool,
    /// Make the x axis include 0.
    pub x_zero: bool,
    /// Make the y axis include 0.
    pub y_zero: bool,
    /// Logarithmic y axis (needs `y_range`; values below it are drawn below the frame and clipped).
    pub y_log: bool,
    /// Logarithmic x axis over the data's positive range (log-spaced periods, frequencies).
    pub x_log: bool,
    /// Fixed x range (SI) instead of the data's.
    pub x_range: Option<(f64, f64)>,
    /// Fixed y range (SI) instead of the data's.
    pub y_range: Option<(f64, f64)>,
    /// The series, drawn in order.
    pub series: Vec<Series>,
    /// Legend placement.
    pub legend: Legend,
    /// Start a new row of the figure's grid with this panel (groups of small multiples, one per row).
    pub new_row: bool,
}

impl Panel {
    /// An empty panel of `y` against `x`, with an inside legend.
    pub fn new(title: impl Into<String>, x: Quantity, y: Quantity) -> Self {
        Self {
            title: title.into(),
            x,
            y,
            x_tight: false,
            x_zero: false,
            y_zero: false,
            y_log: false,
            x_log: false,
            x_range: None,
            y_range: None,
            series: Vec::new(),
            legend: Legend::Inside,
            new_row: false,
        }
    }

    /// The range of the data along x (`axis = 0`) or y (`axis = 1`), SI; `None` if there is none.
    fn data_range(&self, axis: usize) -> Option<(f64, f64)> {
        let mut r: Option<(f64, f64)> = None;
        let mut add = |v: f64| {
            if v.is_finite() {
                r = Some(r.map_or((v, v), |(a, b)| (a.min(v), b.max(v))));
            }
        };
        for s in &self.series {
            match &s.mark {
                Mark::Line { x, y } | Mark::Points { x, y } => {
                    for &v in if axis == 0 { x } else { y } {
                        add(v);
                    }
                }
                Mark::HLine(v) if axis == 1 => add(*v),
                Mark::Rug(t) if axis == 0 => t.iter().for_each(|&v| add(v)),
                _ => {}
            }
        }
        r
    }
}

/// A figure: panels in a grid, a title and an optional subtitle (the inputs in one line).
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Short name, unique within a report; the file stem (`contact-force` → `contact-force.svg`).
    pub id: String,
    /// Title.
    pub title: String,
    /// One line under the title (the inputs).
    pub subtitle: String,
    /// Panels, row by row.
    pub panels: Vec<Panel>,
    /// Panels per row.
    pub columns: usize,
    /// Size of each panel's plot area (inside the frame), px: [`PLOT`] for most figures.
    pub plot: (f64, f64),
    /// Small multiples in one column sharing the time axis: tick labels and the x label only under the
    /// bottom panel, and little space between panels (the panels should be given one `x_range`).
    pub share_x: bool,
    /// Notes under the panels (each one paragraph, wrapped to the figure's width).
    pub notes: Vec<String>,
}

impl Default for Figure {
    fn default() -> Self {
        Self {
            id: String::new(),
            title: String::new(),
            subtitle: String::new(),
            panels: Vec::new(),
            columns: 1,
            plot: PLOT,
            share_x: false,
            notes: Vec::new(),
        }
    }
}

/// The usual plot area, px: wide and low, for histories.
pub const PLOT: (f64, f64) = (620.0, 250.0);
