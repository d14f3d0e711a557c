//! The floor under every contender's tick: the same headless `App` with no physics at all,
//! holding the box's state and the band as our plugin does, driven through the same calls
//! ([`super::PeerRun`]). Our plugin's own cost is then the difference of two ticks timed alike.

use bevy::prelude::*;

use super::{Contender, HeldBox, headless_app, start};
use crate::physics::{BandEnds, BodyState, SceneParams};

pub struct Empty(HeldBox);

impl Contender for Empty {
    const NAME: &'static str = "an empty App";

    fn new(_params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self {
        let mut app = headless_app(rate_hz);
        start(&mut app);
        let body = app
            .world_mut()
            .spawn((initial.linear, initial.angular))
            .id();
        Self(HeldBox::new(app, body))
    }

    fn set_band(&mut self, ends: Option<BandEnds>) {
        self.0.set_band(ends);
    }

    fn state(&mut self) -> BodyState {
        self.0.state()
    }

    fn app(&mut self) -> &mut App {
        &mut self.0.app
    }
}
