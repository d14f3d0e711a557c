use bevy::prelude::*;
use bevy_prototype_lyon::prelude::ShapePlugin;
use rubber_band_box::GamePlugin;

fn main() {
    App::new()
        .insert_resource(ClearColor(Color::BLACK))
        .add_plugins(DefaultPlugins.set(WindowPlugin {
            primary_window: Some(Window {
                title: "Rubber Band Box".into(),
                resolution: (960, 720).into(),
                ..default()
            }),
            ..default()
        }))
        .add_plugins((ShapePlugin, GamePlugin))
        .run();
}
