//! One visual language for every text and chart: the fonts, a type scale, a palette and the
//! spacing, read by the HUD, the panel, the dock and the charts.
//!
//! The fonts are DejaVu Sans (text) and DejaVu Sans Mono (figures of one width, so that a
//! readout's digits keep their place), cut to the characters the game writes
//! (`assets/fonts/`, with their licence) and compiled into the binary, so that they load the
//! same way natively and in the browser. The proportional face replaces Bevy's default font
//! (a 95-glyph ASCII subset with no Greek and no mathematical signs), so every text that
//! names no font gets it.

use bevy::asset::AssetId;
use bevy::math::DVec2;
use bevy::prelude::*;
use bevy::text::FontSource;

use crate::physics::Integrator;

pub struct ThemePlugin;

impl Plugin for ThemePlugin {
    fn build(&self, app: &mut App) {
        // Before anything spawns text (the layout spawns in `Startup`).
        app.add_systems(PreStartup, load_fonts);
    }
}

const TEXT_FACE: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");
const FIGURES_FACE: &[u8] = include_bytes!("../../assets/fonts/DejaVuSansMono-subset.ttf");

/// The figures' face: a handle of its own, fixed so that a text can name it before it loads.
const FIGURES_FONT: Handle<Font> =
    bevy::asset::uuid_handle!("5b1c7e2a-9d04-4f6b-8a31-c2e971d03f55");

/// Puts the two faces in place, the text face as the default font.
///
/// The figures' face goes under [`FIGURES_FONT`]. Without Bevy's text plugin (the headless game)
/// there is nothing to do.
fn load_fonts(fonts: Option<ResMut<Assets<Font>>>) {
    let Some(mut fonts) = fonts else {
        return;
    };
    // Both inserts only fail for a handle that is not a UUID's: these are.
    let _ = fonts.insert(AssetId::default(), Font::from_bytes(TEXT_FACE.to_vec()));
    let _ = fonts.insert(&FIGURES_FONT, Font::from_bytes(FIGURES_FACE.to_vec()));
}

/// The type scale, in logical pixels at a UI scale of 1.
pub mod size {
    /// A card's title, the status line.
    pub const TITLE: f32 = 14.0;
    /// Sentences, buttons, labels.
    pub const BODY: f32 = 13.0;
    /// Numbers that change (the readouts, the ghosts' table).
    pub const READOUT: f32 = 12.0;
    /// Axis ticks, slider ends, the hint line, chart labels.
    pub const CAPTION: f32 = 11.0;
}

/// Spacing, in logical pixels at a UI scale of 1.
pub mod space {
    /// Between a card's lines and its edges.
    pub const PAD: f32 = 6.0;
    /// Between cards and between regions.
    pub const GAP: f32 = 4.0;
}

/// The palette.
pub mod colour {
    /// The ring around the control that has keyboard focus.
    pub const FOCUS: Color = Color::srgb(1.0, 0.85, 0.2);
    use bevy::prelude::Color;

    /// The box's fill.
    pub const BOX_FILL: Color = Color::srgb(0.16, 0.42, 0.72);
    /// The box's outline and centre cross (the tests find the box's gizmos by it).
    pub const BOX_OUTLINE: Color = Color::WHITE;
    /// The band's pin at the pointer, and the trail of the pulled corner.
    pub const PIN_FILL: Color = Color::srgb(1.0, 0.85, 0.2);
    /// The scene's background (the clear colour) and the page around the dock.
    pub const BACKGROUND: Color = Color::srgb(0.05, 0.055, 0.07);
    /// A card's body.
    pub const CARD: Color = Color::srgb(0.11, 0.12, 0.145);
    /// A card's title bar, and a button at rest.
    pub const CARD_TITLE: Color = Color::srgb(0.16, 0.17, 0.2);
    /// A chart's plotting area.
    pub const CHART: Color = Color::srgb(0.07, 0.075, 0.09);
    /// A chart's frame and ticks, and the tutorial screen's border.
    pub const FRAME: Color = Color::srgb(0.3, 0.31, 0.36);
    pub const TEXT: Color = Color::srgb(0.9, 0.9, 0.92);
    pub const DIM: Color = Color::srgb(0.62, 0.63, 0.68);
    pub const WARNING: Color = Color::srgb(1.0, 0.42, 0.32);
    /// A button whose state is on.
    pub const LIT: Color = Color::srgb(0.2, 0.42, 0.7);
    pub const BORDER: Color = Color::srgb(0.35, 0.36, 0.42);
    pub const TRACK: Color = Color::srgb(0.25, 0.26, 0.3);
    pub const THUMB: Color = Color::srgb(0.85, 0.85, 0.9);
    /// The energy graph's lines and the readouts that are its legend.
    pub const KINETIC: Color = Color::srgb(0.35, 0.75, 1.0);
    pub const BAND_ENERGY: Color = Color::srgb(1.0, 0.3, 0.8);
    pub const TOTAL: Color = Color::srgb(1.0, 0.85, 0.2);
    /// The arrows on the box, and learn mode's equations of what they show.
    pub const VELOCITY: Color = Color::srgb(0.3, 0.9, 0.4);
    pub const FORCE: Color = Color::srgb(1.0, 0.55, 0.1);
    /// The arm r, from the centre to the band's corner.
    pub const ARM: Color = Color::srgb(0.45, 0.85, 1.0);
    /// The torque τ, an arc about the centre in its sense.
    pub const TORQUE: Color = Color::srgb(0.8, 0.55, 1.0);
    /// Learn mode's centre twin, its outline and its lines.
    pub const TWIN: Color = Color::srgb(0.75, 0.78, 0.85);
}

/// Returns an integrator's colour, from the core's one table ([`Integrator::colour`]).
///
/// It is the same in the game and the report's figures.
/// The velocity arrow shows where the centre will be in this many seconds.
pub const VELOCITY_ARROW_SECONDS: f32 = 0.25;

/// Returns the force arrow's length, which grows with the logarithm of the force.
///
/// That way k = 20 and k = 1e9 both fit.
fn force_arrow_length(force: f64) -> f64 {
    (30.0 * (1.0 + force / 10.0).log10()).min(300.0)
}

/// Returns the arrow drawn for `force`: along it, as long as its logarithm says.
pub fn force_arrow(force: DVec2) -> DVec2 {
    force.normalize_or_zero() * force_arrow_length(force.length())
}

pub(crate) fn method_colour(integrator: Integrator) -> Color {
    let [r, g, b] = integrator.colour();
    Color::srgb_u8(r, g, b)
}

/// Returns the font of body text, in the text face.
pub(crate) fn text_font(size: f32) -> TextFont {
    TextFont::from_font_size(size)
}

/// Returns the font of figures of one width, in the figures' face.
pub(crate) fn figures_font(size: f32) -> TextFont {
    TextFont {
        font: FontSource::Handle(FIGURES_FONT),
        ..TextFont::from_font_size(size)
    }
}

/// Writes a value as a person reads it, the one format the HUD and the panel share.
///
/// The value is written whole or to three significant digits in the usual range (20, 5, 2.02,
/// 0.05), in powers of ten beyond it (1.0e5, 3.2e-9).
pub fn readable(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 {
        "0".to_owned()
    } else if !value.is_finite() || !(1e-2..1e4).contains(&magnitude) {
        format!("{value:.1e}")
    } else {
        let decimals = (2 - magnitude.log10().floor() as i32).max(0) as usize;
        let text = format!("{value:.decimals$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    }
}

/// Writes a value as [`readable`] does, with three significant digits in powers of ten too.
///
/// Learn mode's equations write their numbers so (τ = 1.23e4, not 1.2e4), so that a learner can
/// check the equation the card writes to a part in a thousand, as in the usual range.
pub fn precise(value: f64) -> String {
    let magnitude = value.abs();
    if value != 0.0 && value.is_finite() && !(1e-2..1e4).contains(&magnitude) {
        format!("{value:.2e}")
    } else {
        readable(value)
    }
}

/// Writes a rate in hertz as every readout shows it: `100 Hz`, `62.5 Hz`.
///
/// The HUD's clock, the status line and the panel all write it so.
pub fn hertz(rate: f64) -> String {
    format!("{} Hz", readable(rate))
}

/// Writes the time scale as every readout shows it: `×1`, `×0.25`.
pub fn times(scale: f64) -> String {
    format!("×{}", readable(scale))
}
