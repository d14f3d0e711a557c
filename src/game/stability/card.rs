//! The dock's Stability card: one line, the live integrator's ω·dt against its limit at this
//! damping and the stiffest band it holds, in the warning colour once past it. Registered with
//! the dock here; nothing outside this folder names it but the game's wiring.

use bevy::prelude::*;

use super::margins::StabilityMargins;
use crate::game::layout::{Card, CardSpec, RegisterCard, Slots, card_line};
use crate::game::theme::readable;
use crate::game::theme::{self, colour, size};
use crate::physics::Integrator;
use crate::physics::stability::{Limit, Margin};

impl Card {
    /// The live integrator's distance from instability.
    pub const STABILITY: Card = Card("stability");
}

/// Registers the card and fills it.
pub(super) fn plugin(app: &mut App) {
    app.add_text_card(
        CardSpec::always(Card::STABILITY, "Stability", 70),
        spawn_line,
        show_line,
    );
}

/// The card's line of text.
#[derive(Component, Debug)]
pub struct StabilityLine;

fn spawn_line(mut commands: Commands, slots: Slots) {
    let Some(card) = slots.card_body(Card::STABILITY) else {
        return;
    };
    commands.spawn((
        Name::new("Stability line"),
        StabilityLine,
        card_line("", theme::text_font(size::BODY), colour::TEXT),
        ChildOf(card),
    ));
}

fn show_line(
    margins: Res<StabilityMargins>,
    integrator: Res<Integrator>,
    mut lines: Query<(&mut Text, &mut TextColor), With<StabilityLine>>,
) {
    let (wanted, wanted_colour) = line(&margins.0, *integrator);
    for (mut text, mut colour) in &mut lines {
        if text.0 != wanted {
            text.0.clone_from(&wanted);
        }
        colour.set_if_neq(TextColor(wanted_colour));
    }
}

/// Returns the card's line for the live integrator and its colour.
///
/// The warning colour once the live method is past its limit (another method past its own is
/// the ghosts' table's business); empty when no margin is known.
pub fn line(margins: &[Margin], live: Integrator) -> (String, Color) {
    match margins.iter().find(|margin| margin.integrator == live) {
        Some(margin) => (
            format!("stability: {}", in_full(margin)),
            if margin.holds {
                colour::TEXT
            } else {
                colour::WARNING
            },
        ),
        None => (String::new(), colour::TEXT),
    }
}

/// Writes out a margin in full.
///
/// It gives ω·dt now against the method's limit at this damping, and the stiffest band it holds.
fn in_full(margin: &Margin) -> String {
    let now = format!("{} at ω·dt {:.2}", margin.integrator, margin.omega_dt);
    match margin.stiffest {
        Limit::Any => format!("{now}, stable at any k"),
        Limit::Never => format!("{now}: UNSTABLE at any k without more damping"),
        Limit::UpTo(k) => {
            let limit = margin.limit_omega_dt.unwrap_or(f64::NAN);
            if margin.holds {
                format!("{now} of {limit:.2}: holds k up to {}", readable(k))
            } else {
                format!(
                    "{now}, past its {limit:.2}: UNSTABLE above k {}",
                    readable(k)
                )
            }
        }
    }
}
