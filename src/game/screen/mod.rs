//! The screen: the camera and the interpolation between fixed steps ([`view`]), the box, the
//! band and the overlays drawn ([`draw`]), the HUD's energy graph ([`graph`]), and the ghosts'
//! speed against error ([`plot`]). Needs
//! rendering; reads the game's state, never the other way round.

pub mod draw;
pub mod graph;
pub mod plot;
pub mod view;
