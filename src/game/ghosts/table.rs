//! The dock's Ghosts card: a table, a row a ghost, of its distance from the reference, its
//! energy residual, its time and work per step, and the stiffest band its method holds (in
//! the warning colour past it, or once the ghost diverged). In the dock only while the ghosts
//! are on; registered with the dock here.

use bevy::picking::Pickable;
use bevy::prelude::*;

use super::steppers::{GhostKind, Ghosts};
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, show_node};
use crate::game::shared::Overlay;
use crate::game::stability::StabilityMargins;
use crate::game::theme::{self, colour, size, space};
use crate::physics::Integrator;
use crate::physics::stability::{Limit, Margin};

impl Card {
    /// The ghosts' table (with the ghosts on).
    pub const GHOSTS: Card = Card("ghosts");
}

/// Registers the card and fills it.
pub(super) fn plugin(app: &mut App) {
    let spec = CardSpec {
        card: Card::GHOSTS,
        title: "Ghosts",
        place: 50,
        offered: |overlays, _| overlays.on(Overlay::Ghosts),
    };
    // The stability card finds the margins; without it (the plugin alone, as the benchmarks
    // run it) the table shows none.
    app.init_resource::<StabilityMargins>()
        .add_text_card(spec, spawn_table, show_table);
}

/// The table's columns.
const COLUMNS: [&str; 6] = [
    "method", "error px", "energy", "ns/step", "evals", "holds k",
];

/// Rows the table has room for: the header, every integrator and the reference.
const ROWS: usize = Integrator::ALL.len() + 2;

/// A cell of the ghosts' table: its row (0 the header) and column.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct GhostCell {
    pub row: usize,
    pub column: usize,
}

/// What the table says about one ghost.
#[derive(Debug, Clone, PartialEq)]
pub struct GhostReading {
    pub name: &'static str,
    /// Its colour, in its outline, its row and its point.
    pub colour: Color,
    /// The live box's integrator.
    pub live: bool,
    pub distance: Option<f64>,
    pub residual: f64,
    pub substeps: u32,
    pub evaluations: u32,
    pub ns_per_step: f64,
    pub diverged_at: Option<u64>,
    pub capped: u64,
}

/// Returns what the table says of every ghost, with `live` the box's integrator.
pub fn readings(ghosts: &Ghosts, live: Integrator) -> Vec<GhostReading> {
    ghosts
        .ghosts
        .iter()
        .map(|ghost| GhostReading {
            name: ghost.kind.name(),
            colour: ghost.kind.colour(),
            live: ghost.kind == GhostKind::Method(live),
            distance: ghosts.distance_from_reference(ghost),
            residual: ghost.residual(),
            substeps: ghost.last.substeps,
            evaluations: ghost.last.evaluations,
            ns_per_step: ghost.ns_per_step,
            diverged_at: ghost.diverged_at,
            capped: ghost.capped,
        })
        .collect()
}

/// Returns the table: a header and a row per ghost, each cell its text.
///
/// A row's cells read left to right: the ghost's distance from the reference, its energy residual,
/// its time and work per step, and the stiffest band its method holds at this step. Empty while the
/// ghosts are off.
pub fn table(ghosts: &[GhostReading], margins: &[Margin]) -> Vec<[String; 6]> {
    if ghosts.is_empty() {
        return Vec::new();
    }
    let mut rows = vec![COLUMNS.map(str::to_owned)];
    for g in ghosts {
        let name = if g.live {
            format!("{} (live)", g.name)
        } else {
            g.name.to_owned()
        };
        let margin = margins.iter().find(|m| m.integrator.name() == g.name);
        let holds = match (margin, g.capped) {
            (Some(margin), _) => stability_short(margin),
            (None, 0) => String::new(),
            (None, capped) => format!("capped {capped}"),
        };
        let work = if g.substeps > 1 {
            format!("{}×{}", g.substeps, g.evaluations)
        } else {
            g.evaluations.to_string()
        };
        let row = match g.diverged_at {
            Some(step) => [
                name,
                "DIVERGED".to_owned(),
                format!("@{step}"),
                String::new(),
                String::new(),
                holds,
            ],
            None => [
                name,
                g.distance.map_or("-".to_owned(), |d| format!("{d:.1e}")),
                format!("{:+.1e}", g.residual),
                format!("{:.0}", g.ns_per_step),
                work,
                holds,
            ],
        };
        rows.push(row);
    }
    rows
}

/// Writes the table as text, a row a line, its cells two spaces apart.
///
/// A test or a terminal reads it.
pub fn lines(ghosts: &[GhostReading], margins: &[Margin]) -> String {
    table(ghosts, margins)
        .iter()
        .map(|row| {
            row.iter()
                .filter(|cell| !cell.is_empty())
                .cloned()
                .collect::<Vec<_>>()
                .join("  ")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// Writes a ghost's margin, short: whether it holds the band and up to which k.
fn stability_short(margin: &Margin) -> String {
    match (margin.stiffest, margin.holds) {
        (Limit::Any, _) => "any k".to_owned(),
        (Limit::Never, _) => "✗ no k".to_owned(),
        (Limit::UpTo(k), true) => format!("k<{}", number(k)),
        (Limit::UpTo(k), false) => format!("✗ k<{}", number(k)),
    }
}

/// Writes a number as a person reads it: whole below 10⁴, two digits in powers of ten above.
fn number(value: f64) -> String {
    if value < 1e4 {
        format!("{value:.0}")
    } else {
        format!("{value:.1e}")
    }
}

/// Spawns the table: a grid, so that its columns line up in any face.
fn spawn_table(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::GHOSTS) else {
        return;
    };
    let grid = commands
        .spawn((
            Name::new("Ghosts' table"),
            Pickable::IGNORE,
            Node {
                display: Display::Grid,
                grid_template_columns: vec![RepeatedGridTrack::auto(COLUMNS.len() as u16)],
                column_gap: px(space::GAP),
                padding: UiRect::all(px(space::GAP)),
                ..default()
            },
            BackgroundColor(colour::CARD),
            ChildOf(card),
        ))
        .id();
    for row in 0..ROWS {
        for column in 0..COLUMNS.len() {
            let font = if column == 0 || row == 0 {
                theme::text_font(size::CAPTION)
            } else {
                theme::figures_font(size::CAPTION)
            };
            commands.spawn((
                GhostCell { row, column },
                Text::default(),
                font,
                TextColor(if row == 0 { colour::DIM } else { colour::TEXT }),
                Pickable::IGNORE,
                Node {
                    justify_self: if column == 0 {
                        JustifySelf::Start
                    } else {
                        JustifySelf::End
                    },
                    ..default()
                },
                ChildOf(grid),
            ));
        }
    }
}

/// Writes each cell from the ghosts now, in its colour; a row with nothing in it takes no room.
fn show_table(
    ghosts: Res<Ghosts>,
    integrator: Res<Integrator>,
    margins: Res<StabilityMargins>,
    mut cells: Query<(&GhostCell, &mut Text, &mut TextColor, &mut Node)>,
) {
    let readings = readings(&ghosts, *integrator);
    let table = table(&readings, &margins.0);
    for (cell, mut text, mut colour, mut node) in &mut cells {
        let content = table
            .get(cell.row)
            .map_or("", |row| row[cell.column].as_str());
        if text.0 != content {
            text.0 = content.to_owned();
        }
        show_node(&mut node, cell.row < table.len());
        let ghost = cell
            .row
            .checked_sub(1)
            .and_then(|index| readings.get(index));
        let wanted = match ghost {
            None => colour::DIM,
            Some(g) if g.diverged_at.is_some() && cell.column > 0 => colour::WARNING,
            Some(g) if cell.column == 0 => g.colour,
            Some(_) if cell.column == 5 && content.starts_with('✗') => colour::WARNING,
            Some(_) => colour::TEXT,
        };
        colour.set_if_neq(TextColor(wanted));
    }
}
