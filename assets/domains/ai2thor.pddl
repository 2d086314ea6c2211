; The world model of the ai2thor primitive set (assets/primitives/ai2thor.toml): AI2-THOR's interaction
; rules as cook2ltl's embedded kitchen applies them (app/cook2ltl/kitchen/rules.py, its object-type rules
; in assets/kitchens/rules.toml). One action per primitive, with the primitive's parameters in call order.
; Written for cook2ltl (MIT licence); read with unified-planning, evaluated by cook2ltl.world.logic.
; A problem's objects and initial facts come from THOR metadata: cook2ltl.world.thor.thor_state.
;
; Kinds are predicates named after THOR's ability flags (fillable = canFillWithLiquid, usable =
; canBeUsedUp, heat-source = isHeatSource, ...) and after the type rules: `fits` (what may be put in or on
; what), `cutter` (a knife type), `splits` (has a slicing rule; an Egg breaks into an EggCracked),
; `pieces-cookable`, `fits-sliced` (where the pieces fit: BreadSliced fits a Toaster, Bread does not),
; `controls` (a stove knob switches its burner), `rinses` (a faucet runs into the sink basin it is
; nearest to), `brewer` (a coffee machine), `floor` (where `drop` puts things), and for liquids `brew`
; (what a coffee machine fills a cup with) and `tap-liquid` (what a faucet fills it with). Slicing
; changes kinds, so they are not all static: the object then stands for its pieces.
; `in` is the direct container; the rules look two levels up or down, as deep as a kitchen nests.
;
; The kitchen `settle`s after every action: what sits, however deep, in a running heat source is hot
; (and cooked if cookable; a running coffee machine fills a cup with coffee), what sits in a cold source
; is cold, what sits in a sink basin under its running faucet is rinsed clean and, if it holds liquid,
; filled with water. Those effects are written into the actions that cause them: putting something into
; or onto such a place, switching a heat source or faucet on, emptying a cup where it is refilled at once,
; cutting food inside a running heat source. So `wait` (THOR's Pass) changes nothing: settle has acted.
; Temperature stays when a thing is taken out or its heat source switched off.
;
; Not modelled: geometry (the executor teleports next to what it acts on: nothing is out of reach but
; what a closed receptacle shuts away), the several pieces cutting makes (the object stands for all of
; them), nesting deeper than two levels, a knob switching several burners (each of THOR's knobs switches
; one), THOR's own heating and cooling over time (the embedded kitchen's settle is instant).
;
; Agreement with the embedded kitchen: tests/world/test_thor_world.py runs 320 random plans (2310 lines,
; 1687 of them run by the kitchen) in 8 of the 30 scenes, and seven cooking scripts, through the model and
; through cook2ltl.kitchen.executor on the embedded kitchen. The model accepts exactly the lines the
; kitchen runs, and after each the facts it predicts are the ones read back from THOR's metadata, but for
; 17 facts (15 in the random plans), all from one cause:
;   - several pieces: cutting makes 7-10 pieces (bread, tomato, potato, ...) and each later call acts on
;     one of them, of the kitchen's choosing, while a name's predicate holds when it holds of any piece.
;     After pick_up(bread) the pieces left behind are still `in` the counter (15 times); after heating
;     one piece, bread is hot and also, in the pieces left out, at room temperature (twice). The test
;     allows these, and the like (a piece in reach where the model's one is shut away), for cut names only.
; One rule both share: breaking a thing with a slicing rule (an egg) splits it as cutting does, so, as for
; cutting, it must be put down first; both refuse it held, or inside what the hand holds (a script sends both).
; Also not modelled, as THOR's kitchens never have them: a running heat source inside a cold source (the
; kitchen lets heat win), a coffee machine standing in a sink basin (the kitchen lets coffee win).
(define (domain ai2thor)
  (:requirements :strips :typing :negative-preconditions :disjunctive-preconditions :equality
                 :existential-preconditions :universal-preconditions :conditional-effects)
  (:types thing)
  (:predicates
    ; kinds: THOR's ability flags, and what the type rules say
    (pickupable ?x - thing) (receptacle ?x - thing) (openable ?x - thing) (toggleable ?x - thing)
    (sliceable ?x - thing) (cookable ?x - thing) (fillable ?x - thing) (dirtyable ?x - thing)
    (breakable ?x - thing) (usable ?x - thing) (heat-source ?x - thing) (cold-source ?x - thing)
    (cutter ?x - thing) (liquid ?x - thing) (brewer ?x - thing) (brew ?l - thing) (tap-liquid ?l - thing)
    (floor ?x - thing) (splits ?x - thing) (pieces-cookable ?x - thing)
    (fits ?x - thing ?r - thing) (fits-sliced ?x - thing ?r - thing)
    (controls ?k - thing ?b - thing) (rinses ?f - thing ?b - thing)
    ; state
    (hand-empty) (holding ?x - thing) (in ?x - thing ?r - thing) (opened ?x - thing) (on ?x - thing)
    (hot ?x - thing) (cold ?x - thing) (room_temperature ?x - thing) (cooked ?x - thing)
    (sliced ?x - thing) (broken ?x - thing) (filled ?x - thing) (filled-with ?x - thing ?l - thing)
    (used_up ?x - thing) (dirty ?x - thing) (clean ?x - thing) ; clean: dirtyable and not dirty
    ; kept up to date by the actions, so that no precondition needs a negated quantifier (Fast Downward's
    ; translator takes minutes over those): shut inside a closed receptacle, or inside something inside one;
    ; inside the held object, or inside something inside it
    (enclosed ?x - thing) (carried ?x - thing))

  ; "Reachable" below: not enclosed (not shut inside a closed receptacle, nor inside something inside one).

  (:action pick_up
    :parameters (?x - thing)
    :precondition (and (pickupable ?x) (hand-empty) (not (broken ?x))
      (not (enclosed ?x)))
    ; what the thing carries stays in it; nothing changes temperature on the way out
    :effect (and (holding ?x) (not (hand-empty))
      (forall (?c - thing) (when (in ?x ?c) (not (in ?x ?c))))
      (forall (?z - thing) (when (in ?z ?x) (carried ?z)))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (carried ?z)))))

  ; Put the held thing in or on ?r; settle then acts on it and on what it carries.
  (:action put
    :parameters (?x - thing ?r - thing)
    :precondition (and (holding ?x) (not (= ?x ?r)) (receptacle ?r) (fits ?x ?r)
      (not (carried ?r))
      (not (and (openable ?r) (not (opened ?r))))
      (not (enclosed ?r)))
    :effect (and (in ?x ?r) (not (holding ?x)) (hand-empty)
      (forall (?z - thing) (when (in ?z ?x) (not (carried ?z))))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (not (carried ?z))))
      ; settle, for the place (?r runs, or ?r sits in what runs) and for the load (?x, what it holds,
      ; what that holds), each case written out: planners ground disjunctions and equalities badly
      (when (and (heat-source ?r) (on ?r)) (and (hot ?x) (not (cold ?x)) (not (room_temperature ?x))))
      (forall (?z - thing) (when (and (heat-source ?r) (on ?r) (in ?z ?x)) (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (forall (?z ?w - thing) (when (and (heat-source ?r) (on ?r) (in ?z ?w) (in ?w ?x)) (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (forall (?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h)) (and (hot ?x) (not (cold ?x)) (not (room_temperature ?x)))))
      (forall (?z ?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?x)) (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (forall (?z ?w ?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?w) (in ?w ?x)) (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (when (and (heat-source ?r) (on ?r) (cookable ?x)) (cooked ?x))
      (forall (?z - thing) (when (and (heat-source ?r) (on ?r) (in ?z ?x) (cookable ?z)) (cooked ?z)))
      (forall (?z ?w - thing) (when (and (heat-source ?r) (on ?r) (in ?z ?w) (in ?w ?x) (cookable ?z)) (cooked ?z)))
      (forall (?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h) (cookable ?x)) (cooked ?x)))
      (forall (?z ?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?x) (cookable ?z)) (cooked ?z)))
      (forall (?z ?w ?h - thing) (when (and (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?w) (in ?w ?x) (cookable ?z)) (cooked ?z)))
      (forall (?l - thing) (when (and (brewer ?r) (heat-source ?r) (on ?r) (brew ?l) (fillable ?x) (not (filled ?x)) (not (broken ?x))) (and (filled ?x) (filled-with ?x ?l))))
      (forall (?z ?l - thing) (when (and (brewer ?r) (heat-source ?r) (on ?r) (in ?z ?x) (brew ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?z ?w ?l - thing) (when (and (brewer ?r) (heat-source ?r) (on ?r) (in ?z ?w) (in ?w ?x) (brew ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?h ?l - thing) (when (and (brewer ?h) (heat-source ?h) (on ?h) (in ?r ?h) (brew ?l) (fillable ?x) (not (filled ?x)) (not (broken ?x))) (and (filled ?x) (filled-with ?x ?l))))
      (forall (?z ?h ?l - thing) (when (and (brewer ?h) (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?x) (brew ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?z ?w ?h ?l - thing) (when (and (brewer ?h) (heat-source ?h) (on ?h) (in ?r ?h) (in ?z ?w) (in ?w ?x) (brew ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (when (and (cold-source ?r)) (and (cold ?x) (not (hot ?x)) (not (room_temperature ?x))))
      (forall (?z - thing) (when (and (cold-source ?r) (in ?z ?x)) (and (cold ?z) (not (hot ?z)) (not (room_temperature ?z)))))
      (forall (?z ?w - thing) (when (and (cold-source ?r) (in ?z ?w) (in ?w ?x)) (and (cold ?z) (not (hot ?z)) (not (room_temperature ?z)))))
      (forall (?h - thing) (when (and (cold-source ?h) (in ?r ?h)) (and (cold ?x) (not (hot ?x)) (not (room_temperature ?x)))))
      (forall (?z ?h - thing) (when (and (cold-source ?h) (in ?r ?h) (in ?z ?x)) (and (cold ?z) (not (hot ?z)) (not (room_temperature ?z)))))
      (forall (?z ?w ?h - thing) (when (and (cold-source ?h) (in ?r ?h) (in ?z ?w) (in ?w ?x)) (and (cold ?z) (not (hot ?z)) (not (room_temperature ?z)))))
      (forall (?f - thing) (when (and (rinses ?f ?r) (on ?f) (dirty ?x)) (and (not (dirty ?x)) (clean ?x))))
      (forall (?z ?f - thing) (when (and (rinses ?f ?r) (on ?f) (in ?z ?x) (dirty ?z)) (and (not (dirty ?z)) (clean ?z))))
      (forall (?z ?w ?f - thing) (when (and (rinses ?f ?r) (on ?f) (in ?z ?w) (in ?w ?x) (dirty ?z)) (and (not (dirty ?z)) (clean ?z))))
      (forall (?f ?b - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (dirty ?x)) (and (not (dirty ?x)) (clean ?x))))
      (forall (?z ?f ?b - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (in ?z ?x) (dirty ?z)) (and (not (dirty ?z)) (clean ?z))))
      (forall (?z ?w ?f ?b - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (in ?z ?w) (in ?w ?x) (dirty ?z)) (and (not (dirty ?z)) (clean ?z))))
      (forall (?f ?l - thing) (when (and (rinses ?f ?r) (on ?f) (tap-liquid ?l) (fillable ?x) (not (filled ?x)) (not (broken ?x))) (and (filled ?x) (filled-with ?x ?l))))
      (forall (?z ?f ?l - thing) (when (and (rinses ?f ?r) (on ?f) (in ?z ?x) (tap-liquid ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?z ?w ?f ?l - thing) (when (and (rinses ?f ?r) (on ?f) (in ?z ?w) (in ?w ?x) (tap-liquid ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?f ?b ?l - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (tap-liquid ?l) (fillable ?x) (not (filled ?x)) (not (broken ?x))) (and (filled ?x) (filled-with ?x ?l))))
      (forall (?z ?f ?b ?l - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (in ?z ?x) (tap-liquid ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))
      (forall (?z ?w ?f ?b ?l - thing) (when (and (rinses ?f ?b) (on ?f) (in ?r ?b) (in ?z ?w) (in ?w ?x) (tap-liquid ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))) (and (filled ?z) (filled-with ?z ?l))))))

  (:action drop
    :parameters (?x - thing)
    :precondition (holding ?x)
    :effect (and (not (holding ?x)) (hand-empty)
      (forall (?f - thing) (when (floor ?f) (in ?x ?f)))
      (forall (?z - thing) (when (in ?z ?x) (not (carried ?z))))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (not (carried ?z))))))

  (:action open
    :parameters (?x - thing)
    :precondition (and (openable ?x) (not (opened ?x)) (not (and (toggleable ?x) (on ?x)))
      (not (enclosed ?x)))
    :effect (and (opened ?x)
      (forall (?z - thing) (when (in ?z ?x) (not (enclosed ?z))))
      ; one level further only through what does not shut itself
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x) (not (openable ?c))) (not (enclosed ?z))))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x) (opened ?c)) (not (enclosed ?z))))))

  (:action close
    :parameters (?x - thing)
    :precondition (and (openable ?x) (opened ?x)
      (not (enclosed ?x)))
    :effect (and (not (opened ?x))
      (forall (?z - thing) (when (in ?z ?x) (enclosed ?z)))
      (forall (?z ?c - thing) (when (and (in ?z ?c) (in ?c ?x)) (enclosed ?z)))))

  ; Breaking: an object with a slicing rule splits as when cut (an egg into a cracked egg, see slice),
  ; so it must be put down first, as for cutting; anything else is broken and spills what it held.
  (:action break
    :parameters (?x - thing)
    :precondition (and (breakable ?x) (not (broken ?x)) (not (and (splits ?x) (or (holding ?x) (carried ?x))))
      (not (enclosed ?x)))
    :effect (and (not (filled ?x))
      (forall (?l - thing) (when (filled-with ?x ?l) (not (filled-with ?x ?l))))
      (when (not (splits ?x)) (broken ?x))
      (when (splits ?x)
        (and (sliced ?x) (pickupable ?x) (not (sliceable ?x)) (not (breakable ?x)) (not (splits ?x))
             (not (pieces-cookable ?x)) (not (fillable ?x)) (not (dirtyable ?x)) (not (usable ?x))
             (not (receptacle ?x)) (not (openable ?x)) (not (toggleable ?x)) (not (dirty ?x)) (not (clean ?x))
             (not (used_up ?x)) (not (opened ?x)) (not (on ?x))))
      (when (and (splits ?x) (pieces-cookable ?x)) (cookable ?x))
      (when (and (splits ?x) (not (pieces-cookable ?x))) (and (not (cookable ?x)) (not (cooked ?x))))
      (when (and (splits ?x) (pieces-cookable ?x)
                 (exists (?h - thing) (and (heat-source ?h) (on ?h)
                   (or (in ?x ?h) (exists (?c - thing) (and (in ?x ?c) (in ?c ?h)))))))
            (cooked ?x))
      (forall (?r - thing) (when (and (splits ?x) (fits-sliced ?x ?r)) (fits ?x ?r)))
      (forall (?r - thing) (when (and (splits ?x) (fits ?x ?r) (not (fits-sliced ?x ?r))) (not (fits ?x ?r))))))

  (:action cook
    :parameters (?x - thing)
    :precondition (and (cookable ?x) (not (cooked ?x))
      (not (enclosed ?x)))
    :effect (cooked ?x))

  ; Cutting needs a knife in hand and the food put down. The food then stands for its pieces, in its
  ; place: pickupable, cookable as the rule says (cooked only if they are and it was, or they lie in a
  ; running heat source), at its temperature, fitting where the pieces fit, nothing else.
  (:action slice
    :parameters (?x - thing)
    :precondition (and (sliceable ?x) (splits ?x) (not (holding ?x)) (not (carried ?x))
      (exists (?k - thing) (and (cutter ?k) (holding ?k)))
      (not (enclosed ?x)))
    :effect (and (sliced ?x) (pickupable ?x) (not (sliceable ?x)) (not (breakable ?x)) (not (splits ?x))
      (not (pieces-cookable ?x)) (not (fillable ?x)) (not (dirtyable ?x)) (not (usable ?x))
      (not (receptacle ?x)) (not (openable ?x)) (not (toggleable ?x)) (not (broken ?x)) (not (filled ?x))
      (not (dirty ?x)) (not (clean ?x)) (not (used_up ?x)) (not (opened ?x)) (not (on ?x))
      (forall (?l - thing) (when (filled-with ?x ?l) (not (filled-with ?x ?l))))
      (when (pieces-cookable ?x) (cookable ?x))
      (when (not (pieces-cookable ?x)) (and (not (cookable ?x)) (not (cooked ?x))))
      (when (and (pieces-cookable ?x)
                 (exists (?h - thing) (and (heat-source ?h) (on ?h)
                   (or (in ?x ?h) (exists (?c - thing) (and (in ?x ?c) (in ?c ?h)))))))
            (cooked ?x))
      (forall (?r - thing) (when (fits-sliced ?x ?r) (fits ?x ?r)))
      (forall (?r - thing) (when (and (fits ?x ?r) (not (fits-sliced ?x ?r))) (not (fits ?x ?r))))))

  ; Switching: a stove burner is switched with its knob (?k controls ?x), which must be in reach.
  (:action turn_on
    :parameters (?x - thing)
    :precondition (or
      (and (toggleable ?x) (not (on ?x)) (not (broken ?x)) (not (and (openable ?x) (opened ?x)))
        (not (enclosed ?x)))
      (and (not (toggleable ?x))
        (exists (?k - thing) (and (controls ?k ?x) (toggleable ?k) (not (on ?k)) (not (broken ?k))
          (not (and (openable ?k) (opened ?k)))
          (not (enclosed ?k))))))
    :effect (and (on ?x)
      (forall (?k - thing) (when (and (controls ?k ?x) (not (toggleable ?x))) (on ?k)))
      (forall (?b - thing) (when (controls ?x ?b) (on ?b)))
      ; settle: what is in a heat source now running (?x, or the burner its knob switches), or in
      ; something there, gets hot, and cooked if cookable
      (forall (?z - thing)
        (when (and (heat-source ?x) (or (in ?z ?x) (exists (?c - thing) (and (in ?z ?c) (in ?c ?x)))))
              (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (forall (?z - thing)
        (when (exists (?h - thing) (and (controls ?x ?h) (heat-source ?h)
                (or (in ?z ?h) (exists (?c - thing) (and (in ?z ?c) (in ?c ?h))))))
              (and (hot ?z) (not (cold ?z)) (not (room_temperature ?z)))))
      (forall (?z - thing)
        (when (and (cookable ?z) (heat-source ?x)
                   (or (in ?z ?x) (exists (?c - thing) (and (in ?z ?c) (in ?c ?x)))))
              (cooked ?z)))
      (forall (?z - thing)
        (when (and (cookable ?z)
                   (exists (?h - thing) (and (controls ?x ?h) (heat-source ?h)
                     (or (in ?z ?h) (exists (?c - thing) (and (in ?z ?c) (in ?c ?h)))))))
              (cooked ?z)))
      ; a coffee machine now running fills an empty cup in it with coffee
      (forall (?z ?l - thing)
        (when (and (brew ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z)) (brewer ?x) (heat-source ?x)
                   (or (in ?z ?x) (exists (?c - thing) (and (in ?z ?c) (in ?c ?x)))))
              (and (filled ?z) (filled-with ?z ?l))))
      ; a faucet now running rinses what is in its basin, and fills an empty cup there with water
      (forall (?z - thing)
        (when (and (dirty ?z)
                   (exists (?b - thing) (and (rinses ?x ?b)
                     (or (in ?z ?b) (exists (?c - thing) (and (in ?z ?c) (in ?c ?b)))))))
              (and (not (dirty ?z)) (clean ?z))))
      (forall (?z ?l - thing)
        (when (and (tap-liquid ?l) (fillable ?z) (not (filled ?z)) (not (broken ?z))
                   (exists (?b - thing) (and (rinses ?x ?b)
                     (or (in ?z ?b) (exists (?c - thing) (and (in ?z ?c) (in ?c ?b)))))))
              (and (filled ?z) (filled-with ?z ?l))))))

  (:action turn_off
    :parameters (?x - thing)
    :precondition (or
      (and (toggleable ?x) (on ?x) (not (broken ?x))
        (not (enclosed ?x)))
      (and (not (toggleable ?x))
        (exists (?k - thing) (and (controls ?k ?x) (toggleable ?k) (on ?k) (not (broken ?k))
          (not (enclosed ?k))))))
    :effect (and (not (on ?x))
      (forall (?k - thing) (when (and (controls ?k ?x) (not (toggleable ?x))) (not (on ?k))))
      (forall (?b - thing) (when (controls ?x ?b) (not (on ?b))))))

  (:action use
    :parameters (?x - thing)
    :precondition (and (usable ?x) (not (used_up ?x))
      (not (enclosed ?x)))
    :effect (used_up ?x))

  (:action fill
    :parameters (?x - thing ?l - thing)
    :precondition (and (liquid ?l) (fillable ?x) (not (broken ?x)) (not (filled ?x))
      (not (enclosed ?x)))
    :effect (and (filled ?x) (filled-with ?x ?l)))

  ; Emptied where a running coffee machine or faucet fills it, it is filled again at once.
  (:action empty
    :parameters (?x - thing)
    :precondition (and (fillable ?x) (filled ?x)
      (not (enclosed ?x)))
    :effect (and (not (filled ?x))
      (forall (?l - thing) (when (filled-with ?x ?l) (not (filled-with ?x ?l))))
      (forall (?l - thing)
        (when (and (brew ?l) (not (broken ?x))
                   (exists (?h - thing) (and (brewer ?h) (heat-source ?h) (on ?h)
                     (or (in ?x ?h) (exists (?c - thing) (and (in ?x ?c) (in ?c ?h)))))))
              (and (filled ?x) (filled-with ?x ?l))))
      (forall (?l - thing)
        (when (and (tap-liquid ?l) (not (broken ?x))
                   (exists (?f ?b - thing) (and (rinses ?f ?b) (on ?f)
                     (or (in ?x ?b) (exists (?c - thing) (and (in ?x ?c) (in ?c ?b)))))))
              (and (filled ?x) (filled-with ?x ?l))))))

  ; THOR's Pass. `wait(x == state)` is this action, after which x must be in state; nothing happens
  ; while waiting that did not happen at once.
  (:action wait
    :parameters ()
    :precondition (and)
    :effect (and))
)
