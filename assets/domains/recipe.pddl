; The cooking world model of the recipe primitive set (assets/primitives/recipe.toml): what each of the
; paper's primitives needs and does, and the processes that change things while the robot waits.
; Written for cook2ltl; read with unified-planning, planned with Fast Downward.
;
; Kinds are static predicates (an oven is openable, switchable and a heater at once); a vessel is what can
; be poured into (a pot, a bowl, a blender; not a plate, an oven or the fridge). Food also goes on or into
; food (cream cheese spread on a tortilla, onion added to the meat, pasta into the water), and a cover on anything.
; `in` is the direct container (the pasta in the pot, the pot on the stovetop); the rules look two levels
; up, which is as deep as a kitchen nests (an egg in a bowl in the fridge).
; Processes act on `wait`: a running heater gets hot and heats what is in it (water boils, butter melts,
; food cooks and browns); a cooler chills, a freezer freezes. Switching and putting act at once.
(define (domain recipe)
  (:requirements :strips :typing :negative-preconditions :disjunctive-preconditions :equality
                 :existential-preconditions :universal-preconditions :conditional-effects)
  (:types thing)
  (:predicates
    ; kinds (static)
    (food ?x - thing) (liquid ?x - thing) (meltable ?x - thing) (portable ?x - thing)
    (receptacle ?x - thing) (openable ?x - thing) (switchable ?x - thing) (heater ?x - thing)
    (cooler ?x - thing) (freezes ?x - thing) (vessel ?x - thing) (hob ?x - thing) (cuts ?x - thing) (covers ?x - thing) (mixes ?x - thing)
    ; state
    (hand-empty) (holding ?x - thing) (in ?x - thing ?y - thing) (opened ?x - thing) (on ?x - thing)
    (hot ?x - thing) (cold ?x - thing) (frozen ?x - thing) (cooked ?x - thing) (boiled ?x - thing)
    (melted ?x - thing) (browned ?x - thing) (sliced ?x - thing) (combined ?x - thing)
    (flipped ?x - thing) (shaken ?x - thing) (tasted ?x - thing) (covered ?x - thing)
    ; shut inside a closed container (or inside something inside one): kept by open and close, so that no
    ; precondition needs a negated quantifier (Fast Downward's translator grounds those exponentially)
    (enclosed ?x - thing))

  (:action pick_up
    :parameters (?x - thing)
    :precondition (and (portable ?x) (hand-empty)
      (not (enclosed ?x)))
    :effect (and (holding ?x) (not (hand-empty))
      (forall (?c - thing) (when (in ?x ?c) (not (in ?x ?c))))))

  (:action put
    :parameters (?x - thing ?y - thing)
    :precondition (and (not (= ?x ?y)) (or (receptacle ?y) (covers ?x) (and (food ?x) (food ?y)))
      (not (holding ?y)) (not (in ?y ?x)) (or (holding ?x) (and (liquid ?x) (or (vessel ?y) (food ?y))))
      (not (and (openable ?y) (not (opened ?y))))
      (not (enclosed ?y)))
    :effect (and (in ?x ?y)
      (when (holding ?x) (and (not (holding ?x)) (hand-empty)))
      (when (covers ?x) (covered ?y))
      (forall (?c - thing) (when (and (in ?x ?c) (not (= ?c ?y))) (not (in ?x ?c))))))

  (:action pour
    :parameters (?x - thing ?y - thing)
    :precondition (and (not (= ?x ?y)) (or (vessel ?y) (and (food ?x) (food ?y))) (not (holding ?y))
      (not (in ?y ?x))
      (or (liquid ?x) (holding ?x) (exists (?c - thing) (and (holding ?c) (in ?x ?c))))
      (not (and (openable ?y) (not (opened ?y))))
      (not (enclosed ?y)))
    :effect (and
      ; a held container is emptied into ?y and stays in hand; anything else poured lands in ?y
      (when (not (and (holding ?x) (receptacle ?x))) (in ?x ?y))
      (when (and (holding ?x) (not (receptacle ?x))) (and (not (holding ?x)) (hand-empty)))
      (forall (?z - thing) (when (and (holding ?x) (receptacle ?x) (in ?z ?x)) (and (in ?z ?y) (not (in ?z ?x)))))
      (forall (?c - thing) (when (and (in ?x ?c) (not (= ?c ?y))) (not (in ?x ?c))))))

  (:action remove
    :parameters (?x - thing ?y - thing)
    :precondition (and (in ?x ?y) (portable ?x) (hand-empty)
      (not (and (openable ?y) (not (opened ?y))))
      (not (enclosed ?y)))
    :effect (and (holding ?x) (not (hand-empty)) (not (in ?x ?y))))

  (:action open
    :parameters (?x - thing)
    :precondition (and (openable ?x) (not (opened ?x)) (not (enclosed ?x)))
    :effect (and (opened ?x)
      (forall (?z - thing) (when (in ?z ?x) (not (enclosed ?z))))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (not (enclosed ?z))))))

  (:action close
    :parameters (?x - thing)
    :precondition (and (openable ?x) (opened ?x))
    :effect (and (not (opened ?x))
      (forall (?z - thing) (when (in ?z ?x) (enclosed ?z)))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (enclosed ?z)))))

  (:action turn_on
    :parameters (?x - thing)
    :precondition (and (switchable ?x) (not (on ?x)) (not (and (openable ?x) (opened ?x)))
      (not (enclosed ?x)))
    :effect (and (on ?x)
      (forall (?z - thing) (when (and (mixes ?x) (in ?z ?x)) (combined ?z)))))

  (:action turn_off
    :parameters (?x - thing)
    :precondition (on ?x)
    :effect (not (on ?x)))

  (:action stir
    :parameters (?x - thing)
    :precondition (and (or (food ?x) (receptacle ?x)) (not (holding ?x))
      (not (enclosed ?x)))
    :effect (and (combined ?x) (forall (?z - thing) (when (and (food ?z) (in ?z ?x)) (combined ?z)))))

  (:action cut
    :parameters (?x - thing)
    :precondition (and (food ?x) (not (liquid ?x)) (not (holding ?x))
      (exists (?k - thing) (and (cuts ?k) (holding ?k)))
      (not (enclosed ?x)))
    :effect (sliced ?x))

  (:action turn
    :parameters (?x - thing)
    :precondition (and (food ?x) (not (liquid ?x))
      (not (enclosed ?x)))
    :effect (flipped ?x))

  (:action shake
    :parameters (?x - thing)
    :precondition (holding ?x)
    :effect (and (shaken ?x) (forall (?z - thing) (when (and (food ?z) (in ?z ?x)) (combined ?z)))))

  (:action taste
    :parameters (?x - thing)
    :precondition (and (food ?x)
      (not (enclosed ?x)))
    :effect (tasted ?x))

  ; Processes: what happens while time passes. `wait` (the primitive) lets every process whose condition holds
  ; act at once; a planner takes them one at a time, and each is written in a plan as a wait for its state
  ; (`wait(egg == boiled)`). An action is a process when its name starts with `process-`. Each is written
  ; once for what sits in the appliance and once for what sits in a container in it.
  (:action process-heater-heats
    :parameters (?h - thing)
    :precondition (and (heater ?h) (on ?h))
    :effect (and (hot ?h) (not (cold ?h))))

  (:action process-heats
    :parameters (?x ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?x ?h))
    :effect (and (hot ?x) (not (cold ?x)) (not (frozen ?x))))

  (:action process-heats-inside
    :parameters (?x ?c ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?c ?h) (in ?x ?c))
    :effect (and (hot ?x) (not (cold ?x)) (not (frozen ?x))))

  (:action process-cooks
    :parameters (?x ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?x ?h) (food ?x) (not (liquid ?x)))
    :effect (and (cooked ?x) (browned ?x)))

  (:action process-cooks-inside
    :parameters (?x ?c ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?c ?h) (in ?x ?c) (food ?x) (not (liquid ?x)))
    :effect (and (cooked ?x) (browned ?x)))

  (:action process-melts
    :parameters (?x ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?x ?h) (meltable ?x))
    :effect (and (melted ?x)))

  (:action process-melts-inside
    :parameters (?x ?c ?h - thing)
    :precondition (and (heater ?h) (on ?h) (in ?c ?h) (in ?x ?c) (meltable ?x))
    :effect (and (melted ?x)))

  (:action process-boils
    :parameters (?x ?c ?h - thing)
    :precondition (and (hob ?h) (on ?h) (in ?c ?h) (in ?x ?c) (liquid ?x))
    :effect (and (boiled ?x)))

  (:action process-boils-in-water
    :parameters (?x ?c ?h ?l - thing)
    :precondition (and (hob ?h) (on ?h) (in ?c ?h) (in ?x ?c) (liquid ?l) (in ?l ?c))
    :effect (and (boiled ?x)))

  (:action process-chills
    :parameters (?x ?f - thing)
    :precondition (and (cooler ?f) (in ?x ?f))
    :effect (and (cold ?x) (not (hot ?x))))

  (:action process-chills-inside
    :parameters (?x ?c ?f - thing)
    :precondition (and (cooler ?f) (in ?c ?f) (in ?x ?c))
    :effect (and (cold ?x) (not (hot ?x))))

  (:action process-freezes
    :parameters (?x ?f - thing)
    :precondition (and (freezes ?f) (in ?x ?f))
    :effect (and (frozen ?x)))

  (:action process-freezes-inside
    :parameters (?x ?c ?f - thing)
    :precondition (and (freezes ?f) (in ?c ?f) (in ?x ?c))
    :effect (and (frozen ?x)))
)
