//! avian2d 0.7 (f64, no colliders): a dynamic body, a static anchor body, and a distance joint
//! with zero rest length and compliance 1/k, the crate's own XPBD spring.

use avian2d::math::Vector;
use avian2d::physics_transform::PhysicsTransformConfig;
use avian2d::prelude::*;
use bevy::prelude::*;

use super::{Contender, headless_app, start, unwrap_angle};
use crate::physics::{AngularState, BandEnds, BodyState, LinearState, SceneParams};

pub struct Avian {
    app: App,
    body: Entity,
    anchor: Entity,
    joint: Option<Entity>,
    stiffness: f64,
    orientation: f64,
}

impl Contender for Avian {
    const NAME: &'static str = "avian2d";

    fn new(params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self {
        let mut app = headless_app(rate_hz);
        // Position and Rotation are the state: no f32 Transform round trip (beyond 256 px it
        // would snap our f64 positions to f32 ones).
        app.insert_resource(PhysicsTransformConfig {
            propagate_before_physics: false,
            transform_to_position: false,
            position_to_transform: false,
            transform_to_collider_scale: false,
        })
        // Without colliders there is no broad phase to run; the contact solver still asks
        // for the narrow phase's settings.
        .add_plugins(
            PhysicsPlugins::default()
                .build()
                .disable::<BvhBroadPhasePlugin>(),
        )
        .init_resource::<NarrowPhaseConfig>()
        .insert_resource(Gravity(Vector::ZERO));
        start(&mut app);
        let mass = params.mass_properties().expect("valid scene");
        let world = app.world_mut();
        let anchor = world
            .spawn((
                RigidBody::Static,
                Position(Vector::ZERO),
                Rotation::IDENTITY,
            ))
            .id();
        let body = world
            .spawn((
                RigidBody::Dynamic,
                Mass(mass.mass() as f32),
                AngularInertia(mass.inertia() as f32),
                Position(initial.linear.position),
                Rotation::radians(initial.angular.orientation),
                LinearVelocity(initial.linear.velocity),
                AngularVelocity(initial.angular.angular_velocity),
                // Both as rates per second: b/m for the velocity, c for the spin.
                LinearDamping(params.linear_damping / params.mass),
                AngularDamping(params.angular_damping),
                SleepingDisabled,
            ))
            .id();
        Self {
            app,
            body,
            anchor,
            joint: None,
            stiffness: params.stiffness,
            orientation: initial.angular.orientation,
        }
    }

    fn set_band(&mut self, band: Option<BandEnds>) {
        let world = self.app.world_mut();
        if let Some(joint) = self.joint.take() {
            world.despawn(joint);
        }
        let Some(band) = band else {
            return;
        };
        world.entity_mut(self.anchor).insert(Position(band.anchor));
        self.joint = Some(
            world
                .spawn(
                    DistanceJoint::new(self.anchor, self.body)
                        .with_local_anchor2(band.local_point)
                        .with_limits(0.0, 0.0)
                        .with_compliance(1.0 / self.stiffness),
                )
                .id(),
        );
    }

    fn state(&mut self) -> BodyState {
        let body = self.app.world().entity(self.body);
        let rotation = body.get::<Rotation>().expect("avian keeps a rotation");
        self.orientation = unwrap_angle(self.orientation, rotation.as_radians());
        BodyState {
            linear: LinearState {
                position: body.get::<Position>().expect("avian keeps a position").0,
                velocity: body
                    .get::<LinearVelocity>()
                    .expect("avian keeps a velocity")
                    .0,
            },
            angular: AngularState {
                orientation: self.orientation,
                angular_velocity: body.get::<AngularVelocity>().expect("avian keeps a spin").0,
            },
        }
    }

    fn app(&mut self) -> &mut App {
        &mut self.app
    }
}
