//! The scene in words, for a screen reader: where the box is, how it moves and turns, whether
//! a band pulls it and which way, and whether the game is paused. Every figure is put into a
//! word or two (left, slowly, clockwise...), so that the description changes only when
//! something a listener would notice has changed, never with each step's last digit.

use bevy::math::DVec2;

use crate::physics::{BodyState, SCENE_SIZE};

/// What the description is made from, this frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seen {
    pub state: BodyState,
    /// The band's anchor and the corner it holds, if a band pulls.
    pub band: Option<(DVec2, DVec2)>,
    pub paused: bool,
}

/// Below this speed (px/s) the box is "still".
const STILL_SPEED: f64 = 5.0;

/// Below this rate (rad/s) the box is "not turning".
const STILL_TURN: f64 = 0.05;

/// Says the scene in one or two sentences.
pub fn describe(seen: &Seen) -> String {
    let state = &seen.state;
    let mut said = String::new();
    if seen.paused {
        said.push_str("Paused. ");
    }
    said.push_str(&format!(
        "The box is {}, {}, {}.",
        place(state.linear.position),
        motion(state.linear.velocity),
        turning(state.angular.angular_velocity)
    ));
    match seen.band {
        Some((anchor, corner)) => said.push_str(&format!(
            " A band pulls a corner {}, {}.",
            way(anchor - corner),
            stretch((anchor - corner).length())
        )),
        None => said.push_str(" No band."),
    }
    said
}

/// Says where a point lies in the tutorial's 640 x 480 frame, in thirds, or off it.
///
/// The frame is centred on the origin.
fn place(at: DVec2) -> String {
    if at.abs().cmpgt(SCENE_SIZE / 2.0).any() {
        return format!(
            "off the frame, {}",
            way(at).replace("up", "above").replace("down", "below")
        );
    }
    let at = at + SCENE_SIZE / 2.0;
    let third = |value: f64, size: f64| (value / size * 3.0).floor().clamp(0.0, 2.0) as usize;
    let row = ["at the bottom", "in the middle", "at the top"][third(at.y, SCENE_SIZE.y)];
    let column = ["left", "centre", "right"][third(at.x, SCENE_SIZE.x)];
    match (row, column) {
        ("in the middle", "centre") => "at the centre of the frame".to_owned(),
        (row, column) => format!("{row} {column} of the frame"),
    }
}

/// Says how fast and which way the box moves.
fn motion(velocity: DVec2) -> String {
    let speed = velocity.length();
    let how = match speed {
        s if s < STILL_SPEED => return "still".to_owned(),
        s if s < 100.0 => "slowly",
        s if s < 400.0 => "",
        _ => "fast",
    };
    let moving = format!("moving {}", way(velocity));
    if how.is_empty() {
        moving
    } else {
        format!("{moving} {how}")
    }
}

/// Says how fast and which way the box turns (counter-clockwise positive, y up).
fn turning(rate: f64) -> String {
    let sense = if rate > 0.0 {
        "counter-clockwise"
    } else {
        "clockwise"
    };
    match rate.abs() {
        r if r < STILL_TURN || !r.is_finite() => "not turning".to_owned(),
        r if r < 1.0 => format!("turning slowly {sense}"),
        r if r < 6.0 => format!("turning {sense}"),
        _ => format!("spinning fast {sense}"),
    }
}

/// Says the way a direction points, in eight words (y up).
fn way(direction: DVec2) -> &'static str {
    if direction.length_squared() == 0.0 || !direction.is_finite() {
        return "nowhere";
    }
    let eighth = (direction.y.atan2(direction.x) / std::f64::consts::FRAC_PI_4).round() as i64;
    [
        "to the right",
        "up and to the right",
        "up",
        "up and to the left",
        "to the left",
        "down and to the left",
        "down",
        "down and to the right",
    ][eighth.rem_euclid(8) as usize]
}

/// Says how far the band is stretched.
fn stretch(length: f64) -> &'static str {
    match length {
        l if l < 20.0 => "hardly stretched",
        l if l < 150.0 => "stretched",
        _ => "stretched far",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::{AngularState, LinearState};

    fn seen(position: DVec2, velocity: DVec2, rate: f64) -> Seen {
        Seen {
            state: BodyState {
                linear: LinearState { position, velocity },
                angular: AngularState {
                    orientation: 0.0,
                    angular_velocity: rate,
                },
            },
            band: None,
            paused: false,
        }
    }

    #[test]
    fn the_words_follow_the_figures() {
        let centre = DVec2::ZERO;
        assert_eq!(
            describe(&seen(centre, DVec2::ZERO, 0.0)),
            "The box is at the centre of the frame, still, not turning. No band."
        );
        let mut pulled = seen(DVec2::new(280.0, -220.0), DVec2::new(-50.0, 50.0), -2.0);
        pulled.band = Some((DVec2::new(480.0, -100.0), DVec2::new(300.0, -200.0)));
        pulled.paused = true;
        assert_eq!(
            describe(&pulled),
            "Paused. The box is at the bottom right of the frame, moving up and to the left \
             slowly, turning clockwise. A band pulls a corner up and to the right, stretched far."
        );
        let flung = describe(&seen(DVec2::new(-900.0, 0.0), DVec2::X * 500.0, 9.0));
        assert!(
            flung.starts_with(
                "The box is off the frame, to the left, moving to the right fast, \
                 spinning fast counter-clockwise."
            ),
            "{flung}"
        );
        // A digit's change says nothing new.
        assert_eq!(
            describe(&seen(centre, DVec2::new(0.1, 0.0), 0.01)),
            describe(&seen(centre + 1.0, DVec2::ZERO, 0.0))
        );
    }
}
