//! The dock's cards: each named and registered by the plugin that fills it ([`Card`],
//! [`CardSpec`], [`RegisterCard`]), which are offered now (by the overlays and the mode), and
//! which are open ([`Cards`]): on the side any number, on a tall window one at a time.

use bevy::ecs::system::{ScheduleSystem, SystemParam};
use bevy::prelude::*;

use super::shape::Shape;
use crate::game::schedule::ScreenSystems;
use crate::game::shared::{Mode, Overlays};

/// An instrument card of the dock, named by the plugin that fills it.
///
/// Each card's own module names it (`Card::STABILITY` in `stability/`) and registers it with
/// the dock ([`RegisterCard::register_card`]); the dock keeps no list of its own.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Card(pub &'static str);

/// A card as its plugin registers it: its name, its title, its place and when it is offered.
#[derive(Debug, Clone, Copy)]
pub struct CardSpec {
    pub card: Card,
    /// The title on its fold button and its tab.
    pub title: &'static str,
    /// Its place in the dock, top to bottom (a tall window's tabs, left to right).
    pub place: u8,
    /// Tells whether the card is in the dock now (the ghosts' table only with the ghosts on).
    pub offered: fn(&Overlays, Mode) -> bool,
}

impl CardSpec {
    /// Returns a card that is always in the dock.
    pub const fn always(card: Card, title: &'static str, place: u8) -> Self {
        Self {
            card,
            title,
            place,
            offered: |_, _| true,
        }
    }
}

/// Every card of the dock in its order: what the plugins registered.
///
/// The dock spawns a frame, a title and a body (`Slot::Card`) for each at start-up.
#[derive(Resource, Debug, Default)]
pub struct CardRegistry(pub(super) Vec<CardSpec>);

impl CardRegistry {
    /// Returns the cards in the dock's order.
    pub fn cards(&self) -> impl Iterator<Item = Card> + '_ {
        self.0.iter().map(|spec| spec.card)
    }

    /// Tells whether `card` is in the dock now; an unregistered card never is.
    pub fn offers(&self, card: Card, overlays: &Overlays, mode: Mode) -> bool {
        self.0
            .iter()
            .any(|spec| spec.card == card && (spec.offered)(overlays, mode))
    }
}

/// Registers cards with the dock.
pub trait RegisterCard {
    /// Registers a card, in the place it asks; a second registration of a name is ignored.
    fn register_card(&mut self, spec: CardSpec) -> &mut Self;

    /// Registers a card that writes its own text, and its two systems.
    ///
    /// `spawn` fills its body at start-up, `write` writes it every frame, in
    /// `ScreenSystems::Write`. The texts' writers run in any order among themselves: each writes only its own texts.
    fn add_text_card<S, W>(
        &mut self,
        spec: CardSpec,
        spawn: impl IntoScheduleConfigs<ScheduleSystem, S>,
        write: impl IntoScheduleConfigs<ScheduleSystem, W>,
    ) -> &mut Self;
}

impl RegisterCard for App {
    fn register_card(&mut self, spec: CardSpec) -> &mut Self {
        let mut registry = self.world_mut().get_resource_or_init::<CardRegistry>();
        if registry.0.iter().any(|known| known.card == spec.card) {
            warn!(
                "the card {:?} is registered twice: the second ignored",
                spec.card
            );
        } else {
            registry.0.push(spec);
            registry.0.sort_by_key(|known| known.place);
        }
        self
    }

    fn add_text_card<S, W>(
        &mut self,
        spec: CardSpec,
        spawn: impl IntoScheduleConfigs<ScheduleSystem, S>,
        write: impl IntoScheduleConfigs<ScheduleSystem, W>,
    ) -> &mut Self {
        self.register_card(spec)
            .add_systems(Startup, spawn)
            .add_systems(
                Update,
                write
                    .in_set(ScreenSystems::Write)
                    .ambiguous_with(ScreenSystems::Write),
            )
    }
}

/// What decides which cards the dock offers now, as a system reads it.
#[derive(SystemParam)]
pub(super) struct Offered<'w> {
    registry: Res<'w, CardRegistry>,
    overlays: Res<'w, Overlays>,
    mode: Res<'w, State<Mode>>,
}

impl Offered<'_> {
    /// Returns what decides the offers now.
    pub(super) fn now(&self) -> Offers<'_> {
        Offers {
            registry: &self.registry,
            overlays: &self.overlays,
            mode: *self.mode.get(),
        }
    }

    /// Returns the cards offered in play with no overlay on: what the dock offers at start.
    pub(super) fn at_start(&self) -> Vec<Card> {
        Offers {
            registry: &self.registry,
            overlays: &Overlays::default(),
            mode: Mode::Play,
        }
        .offered()
    }
}

/// What decides which cards the dock offers now: the cards, the overlays and the mode.
#[derive(Clone, Copy)]
pub(super) struct Offers<'a> {
    pub(super) registry: &'a CardRegistry,
    overlays: &'a Overlays,
    mode: Mode,
}

impl Offers<'_> {
    pub(super) fn offers(&self, card: Card) -> bool {
        self.registry.offers(card, self.overlays, self.mode)
    }

    /// Returns every card offered, in the dock's order.
    pub(super) fn offered(&self) -> Vec<Card> {
        self.registry
            .cards()
            .filter(|&card| self.offers(card))
            .collect()
    }
}

/// Which cards are open, kept as the player left them while the game runs.
///
/// A tall window shows one at a time (the first open one).
#[derive(Resource, Debug, Clone, PartialEq, Eq, Default)]
pub struct Cards {
    open: std::collections::BTreeSet<Card>,
}

impl Cards {
    pub fn is_open(&self, card: Card) -> bool {
        self.open.contains(&card)
    }

    pub fn set(&mut self, card: Card, open: bool) {
        if open {
            self.open.insert(card);
        } else {
            self.open.remove(&card);
        }
    }

    /// Folds or unfolds `card`, as a press on its title does.
    ///
    /// On the side it folds or unfolds; on a tall window, where one card shows at a time, an open
    /// card folds and a folded one opens alone.
    pub fn toggle(&mut self, card: Card, shape: Shape) {
        let open = !self.is_open(card);
        if shape == Shape::Tall && open {
            self.open.clear();
        }
        self.set(card, open);
    }

    /// Returns the card a tall window shows: the first open one the dock offers.
    pub(super) fn shown_alone(&self, offers: &Offers) -> Option<Card> {
        offers
            .registry
            .cards()
            .find(|&card| self.is_open(card) && offers.offers(card))
    }

    /// Tells whether the card's body shows.
    pub(super) fn body_shows(&self, card: Card, shape: Shape, offers: &Offers) -> bool {
        match shape {
            Shape::Wide => self.is_open(card) && offers.offers(card),
            Shape::Tall => self.shown_alone(offers) == Some(card),
        }
    }
}

/// A card's title: a button that folds it (the panel presses it, as its other buttons).
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct CardButton(pub Card);
