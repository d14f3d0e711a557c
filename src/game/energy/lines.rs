//! The Energy card's lines of text: the energies of the state now, the ledger and the
//! integrator's error, formatted here from the simulation's books.

use bevy::ecs::system::SystemParam;
use bevy::prelude::*;

use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, card_line};
use crate::game::simulation::{Band, Bodies, EnergyBooks, mechanical_energies};
use crate::game::theme::{self, colour, size};
use crate::physics::{Energies, EnergyLedger, SceneParams};

impl Card {
    /// The energies, the ledger and the energy graph.
    pub const ENERGY: Card = Card("energy");
}

/// Registers the card and writes its lines.
pub(super) fn plugin(app: &mut App) {
    app.add_text_card(
        CardSpec::always(Card::ENERGY, "Energy", 40),
        spawn_lines,
        show_lines,
    );
}

/// One line of the card, a `Text` entity named "Energy" and the line.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
enum EnergyLine {
    Heading,
    KineticLinear,
    KineticRotational,
    BandPotential,
    Total,
    Ledger,
    Residual,
}

impl EnergyLine {
    /// Every line, in the card's order.
    const ALL: [EnergyLine; 7] = [
        EnergyLine::Heading,
        EnergyLine::KineticLinear,
        EnergyLine::KineticRotational,
        EnergyLine::BandPotential,
        EnergyLine::Total,
        EnergyLine::Ledger,
        EnergyLine::Residual,
    ];

    /// Returns the line's size and face: figures of one width where the energies stand.
    fn font(self) -> TextFont {
        match self {
            EnergyLine::KineticLinear
            | EnergyLine::KineticRotational
            | EnergyLine::BandPotential
            | EnergyLine::Total => theme::figures_font(size::READOUT),
            _ => theme::text_font(size::BODY),
        }
    }

    /// Returns the line's colour: the energies in their graph's colours (the graph's legend).
    fn colour(self) -> Color {
        match self {
            EnergyLine::KineticLinear | EnergyLine::KineticRotational => colour::KINETIC,
            EnergyLine::BandPotential => colour::BAND_ENERGY,
            EnergyLine::Total => colour::TOTAL,
            EnergyLine::Heading => colour::DIM,
            EnergyLine::Ledger | EnergyLine::Residual => colour::TEXT,
        }
    }

    /// Returns what the line says of the readings.
    fn text(self, r: &Readings) -> String {
        let e = &r.energies;
        match self {
            EnergyLine::Heading => "energy (mass · px²/s²)".to_owned(),
            EnergyLine::KineticLinear => format!("  kinetic, linear   {}", energy(e.linear)),
            EnergyLine::KineticRotational => {
                format!("  kinetic, rotation {}", energy(e.rotational))
            }
            EnergyLine::BandPotential => format!("  band potential    {}", energy(e.band)),
            EnergyLine::Total => format!("  total             {}", energy(e.total())),
            EnergyLine::Ledger => format!(
                "  hand's work in {}  damping out {}",
                energy(r.ledger.work_in).trim_start(),
                energy(r.ledger.dissipated).trim_start()
            ),
            EnergyLine::Residual => {
                let throughput = r.ledger.throughput();
                let relative = if throughput > 0.0 {
                    format!("{:.1e}", r.residual.abs() / throughput)
                } else {
                    "-".to_owned()
                };
                format!(
                    "  integrator's error {:+.2e} ({relative} of energy through)",
                    r.residual
                )
            }
        }
    }
}

/// Writes an energy fixed-point in the usual range, in scientific notation outside it.
fn energy(value: f64) -> String {
    // An empty sum is −0.0 in Rust: show it as 0.
    let value = value + 0.0;
    if value == 0.0 || (1e-2..1e7).contains(&value.abs()) {
        format!("{value:>12.2}")
    } else {
        format!("{value:>12.3e}")
    }
}

/// Everything the card's lines show.
#[derive(Debug, Clone, PartialEq)]
struct Readings {
    energies: Energies,
    ledger: EnergyLedger,
    residual: f64,
}

/// What the card reads: the books, and the bodies and the band for the energies now.
#[derive(SystemParam)]
struct Sources<'w, 's> {
    params: Res<'w, SceneParams>,
    books: Res<'w, EnergyBooks>,
    boxes: Bodies<'w, 's>,
    bands: Query<'w, 's, &'static Band>,
}

impl Sources<'_, '_> {
    fn readings(&self) -> Readings {
        Readings {
            // Now, not at the last step: the band moves while paused too.
            energies: mechanical_energies(&self.params, &self.boxes, &self.bands),
            ledger: self.books.ledger,
            residual: self.books.residual(),
        }
    }
}

/// Spawns the lines (before the graph's canvas, which lies under them).
pub(super) fn spawn_lines(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::ENERGY) else {
        return;
    };
    for line in EnergyLine::ALL {
        commands.spawn((
            Name::new(format!("Energy {line:?}")),
            line,
            card_line("", line.font(), line.colour()),
            ChildOf(card),
        ));
    }
}

fn show_lines(sources: Sources, mut lines: Query<(&EnergyLine, &mut Text)>) {
    let readings = sources.readings();
    for (line, mut text) in &mut lines {
        // Only what changed is written, so change detection (and text layout) stays quiet.
        text.set_if_neq(Text(line.text(&readings)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn readings() -> Readings {
        Readings {
            energies: Energies {
                linear: 1.0,
                rotational: 2.0,
                band: 3.0,
            },
            ledger: EnergyLedger::starting_at(0.0),
            residual: 0.0,
        }
    }

    #[test]
    fn large_and_small_energies_switch_to_scientific_notation() {
        let mut r = readings();
        assert!(EnergyLine::Total.text(&r).ends_with("6.00"));
        r.energies.band = 4.2e9;
        r.energies.linear = 3e-5;
        assert!(EnergyLine::BandPotential.text(&r).ends_with("4.200e9"));
        assert!(EnergyLine::KineticLinear.text(&r).ends_with("3.000e-5"));
        // An empty sum of energies is −0.0; it shows as 0.
        r.energies.band = -0.0;
        assert!(EnergyLine::BandPotential.text(&r).ends_with(" 0.00"));
    }

    // The energy lines each say their own reading: the heading, both kinetic parts, the band,
    // the total, and the ledger's work in and damping out.
    #[test]
    fn each_energy_line_says_its_own_reading() {
        let mut r = readings();
        // No energy has passed through yet: no relative error to show.
        assert!(EnergyLine::Residual.text(&r).contains("(- of energy"));
        r.ledger = EnergyLedger {
            work_in: 12.5,
            dissipated: 0.25,
            ..EnergyLedger::starting_at(0.0)
        };
        assert_eq!(EnergyLine::Heading.text(&r), "energy (mass · px²/s²)");
        assert_eq!(
            EnergyLine::KineticLinear.text(&r),
            "  kinetic, linear           1.00"
        );
        assert_eq!(
            EnergyLine::KineticRotational.text(&r),
            "  kinetic, rotation         2.00"
        );
        assert_eq!(
            EnergyLine::BandPotential.text(&r),
            "  band potential            3.00"
        );
        assert_eq!(
            EnergyLine::Total.text(&r),
            "  total                     6.00"
        );
        assert_eq!(
            EnergyLine::Ledger.text(&r),
            "  hand's work in 12.50  damping out 0.25"
        );
        // Beyond two decimals' reach, in powers of ten.
        r.energies.rotational = 3.5e9;
        assert!(
            EnergyLine::KineticRotational.text(&r).ends_with("3.500e9"),
            "{}",
            EnergyLine::KineticRotational.text(&r)
        );
    }

    // The residual said against the energy that passed through, once some has: 2e-6 J of
    // error in 100 J moved by the hand and 50 J damped out is 1.3e-8 of it.
    #[test]
    fn the_residual_is_said_against_the_energy_through() {
        let mut ledger = EnergyLedger::starting_at(0.0);
        ledger.hand(100.0);
        ledger.dissipated = 50.0;
        let r = Readings {
            ledger,
            residual: 2e-6,
            ..readings()
        };
        assert_eq!(
            EnergyLine::Residual.text(&r),
            "  integrator's error +2.00e-6 (1.3e-8 of energy through)"
        );
    }

    // The energies in the graph's colours (the lines are its legend), the heading dim, the
    // ledger's lines plain text.
    #[test]
    fn each_line_has_its_colour() {
        assert_eq!(EnergyLine::KineticLinear.colour(), colour::KINETIC);
        assert_eq!(EnergyLine::KineticRotational.colour(), colour::KINETIC);
        assert_eq!(EnergyLine::BandPotential.colour(), colour::BAND_ENERGY);
        assert_eq!(EnergyLine::Total.colour(), colour::TOTAL);
        assert_eq!(EnergyLine::Heading.colour(), colour::DIM);
        assert_eq!(EnergyLine::Ledger.colour(), colour::TEXT);
        assert_eq!(EnergyLine::Residual.colour(), colour::TEXT);
    }
}
