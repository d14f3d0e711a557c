//! bevy_rapier2d 0.36 (rapier 0.35, f32 only): a dynamic body with its mass properties and no
//! collider, a fixed anchor body, and rapier's spring joint (force-based, rest length 0).

use bevy::prelude::*;
use bevy_rapier2d::prelude::*;
use bevy_rapier2d::rapier::dynamics::IntegrationParameters;

use super::{Contender, headless_app, start, unwrap_angle};
use crate::physics::{AngularState, BandEnds, BodyState, LinearState, SceneParams};

pub struct Rapier {
    app: App,
    body: Entity,
    anchor: Entity,
    stiffness: f64,
    orientation: f64,
}

impl Contender for Rapier {
    const NAME: &'static str = "bevy_rapier2d";

    fn new(params: &SceneParams, initial: BodyState, rate_hz: f64) -> Self {
        let mut app = headless_app(rate_hz);
        let integration_parameters = IntegrationParameters {
            // Rapier caps speeds at 400 length units per second by default (one unit is a
            // metre to it); our units are pixels, and the scene moves faster.
            normalized_max_linear_velocity: f32::MAX,
            ..default()
        };
        app.add_plugins(TransformPlugin)
            .insert_resource(TimestepMode::Fixed {
                dt: (1.0 / rate_hz) as f32,
                substeps: 1,
            })
            .add_plugins(
                RapierPhysicsPlugin::<NoUserData>::default()
                    .with_custom_initialization(
                        RapierContextInitialization::InitializeDefaultRapierContext {
                            integration_parameters,
                            rapier_configuration: RapierConfiguration {
                                gravity: Vec2::ZERO,
                                ..RapierConfiguration::new(1.0)
                            },
                        },
                    )
                    .in_fixed_schedule(),
            );
        start(&mut app);
        let mass = params.mass_properties().expect("valid scene");
        let world = app.world_mut();
        let anchor = world.spawn((RigidBody::Fixed, Transform::default())).id();
        let body = world
            .spawn((
                RigidBody::Dynamic,
                Transform::from_translation(initial.linear.position.as_vec2().extend(0.0))
                    .with_rotation(Quat::from_rotation_z(initial.angular.orientation as f32)),
                Velocity {
                    linear: initial.linear.velocity.as_vec2(),
                    angular: initial.angular.angular_velocity as f32,
                },
                AdditionalMassProperties::MassProperties(MassProperties {
                    local_center_of_mass: Vec2::ZERO,
                    mass: mass.mass() as f32,
                    principal_inertia: mass.inertia() as f32,
                }),
                // Both as rates per second: b/m for the velocity, c for the spin.
                Damping {
                    linear_damping: (params.linear_damping / params.mass) as f32,
                    angular_damping: params.angular_damping as f32,
                },
                Sleeping::disabled(),
            ))
            .id();
        Self {
            app,
            body,
            anchor,
            stiffness: params.stiffness,
            orientation: initial.angular.orientation,
        }
    }

    fn set_band(&mut self, band: Option<BandEnds>) {
        let world = self.app.world_mut();
        let Some(band) = band else {
            world.entity_mut(self.body).remove::<ImpulseJoint>();
            return;
        };
        world
            .entity_mut(self.anchor)
            .insert(Transform::from_translation(
                band.anchor.as_vec2().extend(0.0),
            ));
        let spring = SpringJointBuilder::new(0.0, self.stiffness as f32, 0.0)
            .local_anchor1(Vec2::ZERO)
            .local_anchor2(band.local_point.as_vec2());
        world
            .entity_mut(self.body)
            .insert(ImpulseJoint::new(self.anchor, spring));
    }

    fn state(&mut self) -> BodyState {
        let body = self.app.world().entity(self.body);
        let transform = body
            .get::<Transform>()
            .expect("rapier writes the transform");
        let velocity = body.get::<Velocity>().expect("the body has a velocity");
        let (angle, _, _) = transform.rotation.to_euler(EulerRot::ZYX);
        self.orientation = unwrap_angle(self.orientation, f64::from(angle));
        BodyState {
            linear: LinearState {
                position: transform.translation.truncate().as_dvec2(),
                velocity: velocity.linear.as_dvec2(),
            },
            angular: AngularState {
                orientation: self.orientation,
                angular_velocity: f64::from(velocity.angular),
            },
        }
    }

    fn app(&mut self) -> &mut App {
        &mut self.app
    }
}
