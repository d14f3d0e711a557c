//! A small window starts with the dock hidden: where an open card would leave the scene less
//! than half the window, by area, the dock goes (as `H` puts it away) and the status line says
//! how to bring it back. Until the player, a link or learn mode sets the dock, each new window
//! size is judged again, so a browser's first frames at the default size decide nothing for
//! good. Nothing is drawn over the scene: the dock is a region, shown or not.

use bevy::prelude::*;
use bevy::window::PrimaryWindow;

use super::shape::{SHEET_SHARE, Shape, dock_width, ui_scale_for};
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{Apply, DockHidden, Mode, Say};
use crate::game::theme::size;

/// Judges each new window size, until someone else sets the dock.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<SmallWindow>()
        .add_observer(note_who_set_the_dock)
        .add_systems(
            Update,
            // Learn mode's chapter is in the dock: the mode shows it at any size.
            fit_the_dock_to_the_window
                .run_if(in_state(Mode::Play))
                .in_set(ScreenSystems::Arrange),
        );
}

/// What the rule has judged, and whether it still has a say.
#[derive(Resource, Debug, Default)]
pub struct SmallWindow {
    /// The window size judged last.
    judged: Option<Vec2>,
    /// The dock this rule has asked for and not yet seen applied.
    asked: Option<bool>,
    /// The rule hid the dock (so a window grown large shows it again).
    hid: bool,
    /// The player, a link or learn mode has set the dock: the rule is done.
    done: bool,
}

impl SmallWindow {
    /// Tells whether the dock is hidden by this rule, not by the player, a link or learn mode.
    ///
    /// A link shared then leaves the dock out: it is the window's, not the game's.
    pub fn hid_the_dock(&self) -> bool {
        self.hid && !self.done
    }
}

/// The least share of the window the scene keeps before the dock starts hidden.
const LEAST_SCENE_SHARE: f32 = 0.5;

/// Returns the scene's share of a window, by area, with a card open in the dock.
///
/// On a wide window the dock takes its width at the side; on a tall one its sheet takes up to
/// `SHEET_SHARE` of the height. The status line and the hint take a line each.
pub fn scene_share_with_a_card_open(window: Vec2) -> f32 {
    let scale = ui_scale_for(window);
    // A line of body text with its padding, above the scene and below it.
    let lines = 2.0 * (size::BODY * 1.25 + 6.0) * scale;
    let (width, height) = match Shape::of(window) {
        Shape::Wide => (
            window.x - dock_width(window.x / scale) * scale,
            window.y - lines,
        ),
        Shape::Tall => (window.x, window.y * (1.0 - SHEET_SHARE) - lines),
    };
    (width.max(0.0) * height.max(0.0)) / (window.x * window.y).max(1.0)
}

/// Hides the dock on a window too small for it, and shows it again if the window grows.
fn fit_the_dock_to_the_window(
    windows: Query<&Window, With<PrimaryWindow>>,
    dock: Res<DockHidden>,
    mut rule: ResMut<SmallWindow>,
    mut commands: Commands,
) {
    let Some(window) = windows.iter().next().map(Window::size) else {
        return;
    };
    if rule.done || rule.judged == Some(window) || window.min_element() < 1.0 {
        return;
    }
    rule.judged = Some(window);
    let small = scene_share_with_a_card_open(window) < LEAST_SCENE_SHARE;
    let wanted = if small { true } else { dock.0 && !rule.hid };
    if wanted != dock.0 {
        rule.asked = Some(wanted);
        rule.hid = wanted;
        commands.trigger(Apply(DockHidden(wanted)));
        if wanted {
            commands.trigger(Say(
                "a small window: the dock is hidden so the scene has room (H or \"instruments\" \
                 shows it)"
                    .to_owned(),
            ));
        }
    }
}

/// Notes a dock set by anyone but this rule: from then on the dock is theirs.
fn note_who_set_the_dock(apply: On<Apply<DockHidden>>, mut rule: ResMut<SmallWindow>) {
    if rule.asked == Some(apply.0.0) {
        rule.asked = None;
    } else {
        rule.done = true;
    }
}
