//! Each integrator's margin from instability at the present settings, worked out again only
//! when the scene's parameters or `auto`'s settings change, before the step they act on.

use bevy::prelude::*;

use crate::game::schedule::GameSystems;
use crate::physics::stability::{Margin, margins};
use crate::physics::{AutoSettings, SceneParams};

/// Keeps the margins up to date.
pub(super) fn plugin(app: &mut App) {
    app.init_resource::<StabilityMargins>().add_systems(
        RunFixedMainLoop,
        work_out_margins
            .run_if(resource_changed::<SceneParams>.or_eager(resource_changed::<AutoSettings>))
            .in_set(GameSystems::ApplySettings),
    );
}

/// Every integrator's margin at the present parameters and step, in `Integrator::ALL`'s order.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct StabilityMargins(pub Vec<Margin>);

fn work_out_margins(
    params: Res<SceneParams>,
    auto: Res<AutoSettings>,
    mut found: ResMut<StabilityMargins>,
) {
    found.0 = margins(&params, &auto);
}
