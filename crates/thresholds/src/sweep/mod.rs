//! Sweeps: V_stick, V_frag and their companions over a grid of materials, surface energies,
//! radii, partner radii, relaxation times and k.
//!
//! The grid is the product of its axes in the order material, gamma_sv, radius, radius2, t_vis,
//! k (outermost first); [`Grid::index`] numbers its points in that order. It is computed in
//! [`Chunk`]s: one chunk holds every T_vis of one combination of the other axes, in increasing
//! order of the T_vis axis, and each search after the first is seeded with its neighbours'
//! thresholds, extrapolated from the previous three (as [`crate::sweep_t_vis`]). Every front end
//! (the CLI's `stickiness sweep`, the Python `stickiness.sweep` in process or on a Dask cluster)
//! computes the same chunks the same way, so they give the same numbers, and a chunk computed
//! twice (a retried task, a resumed file) gives the same rows. A chunk can start part-way, from
//! the hints its last written rows give ([`Chunk::compute_from`], [`remaining`]): a resumed
//! sweep equals an uninterrupted one.
//!
//! - [`grid`](mod@grid): [`Grid`], [`Point`], [`Chunk`], [`Laws`];
//! - [`axis`]: axes as written (`1e-6,3e-6` or `START:STOP:N`), the one [`geomspace`];
//! - [`row`]: [`Row`], the columns, the header and the CSV / JSON Lines form of a row;
//! - [`resume`]: the rows of an interrupted file and what is left to compute.

pub mod axis;
pub mod grid;
pub mod resume;
pub mod row;

pub use axis::{canonical, geomspace, parse_axis, AxisError, MAX_AXIS_VALUES};
pub use grid::{
    Chunk, Grid, GridError, Laws, NamedMaterial, Partner, Point, TVisAxis, MAX_GRID_POINTS,
};
pub use resume::{
    check_rows, file_text, remaining, verify_rows, written_rows, BadRow, Remaining, VerifyError,
    Written,
};
pub use row::{
    header_lines, header_text, hint_of, point_cells, row_fields, row_text, Cell, Format, Row,
    COLUMNS, INPUT_COLUMNS, UNITS, WARNINGS_SEPARATOR,
};
