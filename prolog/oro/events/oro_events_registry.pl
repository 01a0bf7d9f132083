:- module(oro_events_registry,
          [ watcher/5,                  % ?Id, ?Model, ?Registry, ?Spec, ?Query
            watcher_state/2,            % ?Id, ?State
            watcher_value/2,            % ?Value, ?Id
            watcher_dep/3,              % ?Model, ?PredicateOrAny, ?Id
            watcher_trigger/5,          % ?Key, ?Model, ?Predicate, ?Anchor, ?Id
            watcher_type_open/2,        % ?Model, ?Id
            watcher_plan/2,             % ?Id, ?Plan
            subscription/2,             % ?Id, ?Subscriber
            watching/0,
            pending/0,
            depended_on/2,              % +Model, +P
            class_watcher/4,            % +SchemaKey, +Model, +Class, -Id
            trigger_key/4,              % +Model, +Q, +Anchor, -Key
            by_registration/2,          % +Ids0, -Ids
            watcher_index/5,            % +Spec, +Model, +Query, +State, -Index
            set_index/3,                % +Id, +Model, +Index
            join_variant/5,             % +Model, +Registry, +Spec, +Subscriber, -Id
            add_watcher/9,              % +Id, +Model, +Registry, +Spec, +Query,
                                        % +State, +Values, +Index, +Subscriber
            apply_outcome/4,            % +Outcome, +Id, +State0, -State
            drop_watcher/1,             % +Id
            drop_all_watchers/0,
            unsubscribe/1               % +Subscriber
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(settings)).
:- use_module(library(ordsets)).
:- use_module(library(oro/reason/oro_reason)).

/** <module> Events: the registry of watchers and their index

The tables of the watchers (see oro_events for the whole design): each
watcher's query and state, the values it holds, its subscriptions, and
its index -- the dependencies the writers read to decide whether to
send a change at all, the triggers and plans the watcher thread reads
to decide which watchers a change concerns and how to evaluate them.
This module owns these tables and is the only one that changes them;
only the watcher thread (oro_events_eval) calls the predicates that do,
while the writers' monitor (oro_events_monitor) reads the dependencies
and type triggers.  It also declares the settings `oro_events:index`,
`oro_events:incremental` and `oro_events:warm_schemas` (documented in
oro_events), which the monitor and the watcher thread read.
*/

:- setting(oro_events:incremental, boolean, true,
           'Evaluate watchers from the changed triples where sound; \c
            false re-evaluates every affected watcher in full').
:- setting(oro_events:index, boolean, true,
           'Select the watchers a change may affect by their dependencies; \c
            false (a reference for tests) evaluates every watcher of the \c
            changed models in full at every change').
:- setting(oro_events:warm_schemas, boolean, true,
           'The watcher thread, when idle, compiles the schema tables of \c
            the models that have none for the current schema (false: the \c
            first query of a model after a schema change compiles them)').

%!  watcher(?Id, ?Model, ?Registry, ?Spec, ?Query) is nondet.
%!  watcher_state(?Id, ?State) is nondet.
%!  watcher_value(?Value, ?Id) is nondet.
%!  watcher_dep(?Model, ?PredicateOrAny, ?Id) is nondet.
%!  watcher_trigger(?Key, ?Model, ?Predicate, ?Anchor, ?Id) is nondet.
%!  watcher_type_open(?Model, ?Id) is nondet.
%!  watcher_plan(?Id, ?Plan) is nondet.
%!  subscription(?Id, ?Subscriber) is nondet.
%
%   The tables of the registry, exported for reading only (changed
%   here alone).  A watcher is watcher(Id, Model, Registry,
%   spec(Type, Trigger, Var, Patterns), query(Template, Triples)); its
%   state is `unknown`, truth(Bool) or `values` (one watcher_value/2 a
%   value); its index is as set_index/3 installs it.

:- dynamic
    watcher/5,                      % Id, Model, Registry, Spec, Query
    watcher_variant/2,              % Key, Id (see variant_key/4)
    watcher_seq/2,                  % Id, Seq (registration order)
    watcher_state/2,                % Id, unknown|truth(Bool)|values
    watcher_value/2,                % Value, Id
    watcher_dep/3,                  % Model, PredicateOrAny, Id
    watcher_trigger/5,              % Key, Model, Predicate, Anchor, Id
    watcher_type_class/3,           % Class, Model, Id
    watcher_type_open/2,            % Model, Id
    watcher_plan/2,                 % Id, Plan
    subscription/2.                 % Id, Subscriber

		 /*******************************
		 *           REGISTRY           *
		 *******************************/

%!  watching is semidet.
%
%   Some watcher is registered (the flag oro_events_watchers, which
%   the watcher thread counts: see oro_events_eval, collect_dropped/0).

watching :-
    flag(oro_events_watchers, N, N),
    N > 0.

%!  pending is semidet.
%
%   A change that no watcher depends on (none of its Model-P pairs
%   followed, see touch/5) is not sent at all.  The
%   dependencies are those of the watchers the watcher thread knows, so
%   while it has not yet processed a registration or a schema change
%   (which may change dependencies) every change is sent: the counter
%   oro_events_pending is raised, under the store's write lock, when one
%   is queued and lowered by the watcher thread once it is done.

pending :-
    flag(oro_events_pending, N, N),
    N > 0.

%!  depended_on(+Model, +P) is semidet.
%
%   Some watcher of Model depends on triples of predicate P (or on any
%   change), as the watcher thread last
%   indexed it (set_index/3).

depended_on(Model, P) :-
    (   watcher_dep(Model, any, _)
    ;   watcher_dep(Model, P, _)
    ),
    !.

%!  join_variant(+Model, +Registry, +Spec, +Subscriber, -Id) is semidet.
%
%   A watcher identical to Spec (a variant) of Model in
%   Registry exists, Id; Subscriber is subscribed to it.

join_variant(Model, Registry, Spec, Subscriber, Id) :-
    variant_key(Model, Registry, Spec, Key),
    watcher_variant(Key, Id),
    watcher(Id, Model, Registry, Spec0, _),
    Spec0 =@= Spec,                     % the same: term patterns have variables
    !,
    (   subscription(Id, Subscriber)
    ->  true
    ;   assertz(subscription(Id, Subscriber))
    ).

%!  add_watcher(+Id, +Model, +Registry, +Spec, +Query, +State, +Values,
%!              +Index, +Subscriber) is det.
%
%   Install a new watcher, its initial
%   State and Values, its Index, and subscribe Subscriber to it.

add_watcher(Id, Model, Registry, Spec, Query, State, Values, Index, Subscriber) :-
    flag(oro_watcher_seq, Seq, Seq+1),
    assertz(watcher(Id, Model, Registry, Spec, Query)),
    variant_key(Model, Registry, Spec, Key),
    assertz(watcher_variant(Key, Id)),
    flag(oro_events_watchers, N, N+1),
    assertz(watcher_seq(Id, Seq)),
    assertz(watcher_state(Id, State)),
    forall(member(V, Values), assertz(watcher_value(V, Id))),
    set_index(Id, Model, Index),
    assertz(subscription(Id, Subscriber)).

%   variant_key(+Model, +Registry, +Spec, -Key): the key under which
%   watcher_variant/2 finds the watchers identical to Spec (its
%   variants: term patterns have variables) of Model in Registry, so
%   that a registration joins an identical watcher in one hashed lookup
%   whatever the number of watchers; the candidates it finds are
%   compared with =@=/2.  Attributes of the variables are ignored.

variant_key(Model, Registry, Spec, Key) :-
    copy_term_nat(Spec, Plain),
    variant_sha1(v(Model, Registry, Plain), Key).

%!  apply_outcome(+Outcome, +Id, +State0, -State) is det.
%
%   Record in watcher Id's state the Outcome of an evaluation
%   (truth(Bool), or diff(Added, Removed) of its values).

apply_outcome(truth(Truth), Id, _, truth(Truth)) :-
    retractall(watcher_state(Id, _)),
    assertz(watcher_state(Id, truth(Truth))).
apply_outcome(diff(Added, Removed), Id, State, State) :-
    forall(member(V, Removed), retractall(watcher_value(V, Id))),
    forall(member(V, Added), assertz(watcher_value(V, Id))).

%!  drop_watcher(+Id) is det.
%
%   Forget watcher Id, its state, index and subscriptions (nothing if
%   it is gone already).

drop_watcher(Id) :-
    (   retract(watcher(Id, Model, Registry, Spec, _))
    ->  variant_key(Model, Registry, Spec, Key),
        retractall(watcher_variant(Key, Id)),
        flag(oro_events_watchers, N, N-1),
        flag(oro_events_dropped, D, D+1)
    ;   true
    ),
    retractall(watcher_seq(Id, _)),
    retractall(watcher_state(Id, _)),
    retractall(watcher_value(_, Id)),
    retractall(watcher_dep(_, _, Id)),
    retractall(watcher_trigger(_, _, _, _, Id)),
    retractall(watcher_type_class(_, _, Id)),
    retractall(watcher_type_open(_, Id)),
    retractall(watcher_plan(Id, _)),
    retractall(subscription(Id, _)).

drop_if_orphan(Id) :-
    (   subscription(Id, _)
    ->  true
    ;   drop_watcher(Id)
    ).

%!  drop_all_watchers is det.
%
%   Forget every watcher and subscription (a reset).

drop_all_watchers :-
    aggregate_all(count, watcher(_, _, _, _, _), Count),
    retractall(watcher(_, _, _, _, _)),
    flag(oro_events_watchers, _, 0),
    flag(oro_events_dropped, Dropped, Dropped+Count),
    retractall(watcher_variant(_, _)),
    retractall(watcher_seq(_, _)),
    retractall(watcher_state(_, _)),
    retractall(watcher_value(_, _)),
    retractall(watcher_dep(_, _, _)),
    retractall(watcher_trigger(_, _, _, _, _)),
    retractall(watcher_type_class(_, _, _)),
    retractall(watcher_type_open(_, _)),
    retractall(watcher_plan(_, _)),
    retractall(subscription(_, _)).

%!  unsubscribe(+Subscriber) is det.
%
%   Remove the subscriptions of Subscriber; the watchers left without
%   subscribers are dropped.

unsubscribe(Subscriber) :-
    forall(retract(subscription(Id, Subscriber)),
           drop_if_orphan(Id)).

%!  class_watcher(+SchemaKey, +Model, +Class, -Id) is nondet.
%
%   Watcher Id of Model is anchored by a super-class of Class (in the schema tables SchemaKey):
%   a triple `s rdf:type Class` may change it.  The watcher thread asks
%   it with the schema of the change (triggered/6), the writers with the
%   shared one (triple_followed/5).

class_watcher(SchemaKey, Model, Class, Id) :-
    atom(Class),
    oro_schema_superclass(SchemaKey, Class, Super),
    watcher_type_class(Super, Model, Id).

%!  by_registration(+Ids0, -Ids) is det.
%
%   Ids0 in registration order: watchers are evaluated in the order
%   they were registered, so that
%   two firings of one change reach a subscriber in a stable order.

by_registration(Ids0, Ids) :-
    findall(Seq-Id, ( member(Id, Ids0),
                      watcher_seq(Id, Seq)
                    ), Pairs0),
    sort(Pairs0, Pairs),
    pairs_values(Pairs, Ids).

		 /*******************************
		 *            INDEX             *
		 *******************************/

%!  watcher_index(+Spec, +Model, +Query, +State, -Index) is det.
%
%   Index is index(Deps, Triggers, Plan) for a watcher, computed with
%   the schema of Model (see the module doc):
%
%     - Deps: `[any]` or the predicates whose triples may change it;
%     - Triggers: Predicate-Anchor pairs, Anchor `none`, res(R),
%       class(C), or `chain` and chain(C) for a pattern through a
%       transitive property (chain_watcher/6) (none when Deps is
%       `[any]`);
%     - Plan: `full`, `static` (a new_instance watcher whose variable
%       is not in its patterns) or items(Items), one
%       item(I, Kind, PDeps, Anchored) per pattern: its index I, its
%       Kind (`step`, `type` or trans(Transitives)), its own
%       dependencies (`any` or an ordset) and whether the template
%       variable is its subject or object (`true` or `false`).

watcher_index(Spec, Model, query(Template, Triples), State, index(Deps, Triggers, Plan)) :-
    watcher_deps(Spec, Model, Triples, State, Deps),
    watcher_plan(Spec, Model, Template, Triples, Plan),
    (   Deps == [any]
    ->  Triggers = []
    ;   Plan = items(Items)
    ->  findall(Q-Anchor, ( member(Item, Items),
                            item_trigger(Item, Triples, Q, Anchor)
                          ), Triggers0),
        sort(Triggers0, Triggers)
    ;   findall(Q-none, member(Q, Deps), Triggers)
    ).

%   A fact_checking watcher not evaluated yet depends on any change (it
%   fires at the first one if already true); so do one-shot triggers
%   without edge detection, which fire at any change (ORO-SPEC §7.3).

watcher_deps(spec(fact_checking, Trigger, _, _), _, _, State, [any]) :-
    (   State == unknown
    ;   memberchk(Trigger, [on_true_one_shot, on_false_one_shot])
    ),
    !.
watcher_deps(_, Model, Triples, _, Deps) :-
    oro_pattern_dependencies(Model, Triples, Deps).

watcher_plan(spec(new_instance, _, _, _), _, Template, _, static) :-
    nonvar(Template),
    !.
watcher_plan(_, Model, Template, Triples, Plan) :-
    findall(Item, ( nth1(I, Triples, Triple),
                    pattern_item(Model, Template, I, Triple, Item)
                  ), Items),
    (   memberchk(item(_, full, _, _), Items)
    ->  Plan = full
    ;   Plan = items(Items)
    ).

pattern_item(Model, Template, I, rdf(S, P, O), item(I, Kind, Deps, Anchored)) :-
    oro_pattern_dependencies(Model, [rdf(S, P, O)], Deps0),
    (   Deps0 == [any]
    ->  Deps = any
    ;   Deps = Deps0
    ),
    pattern_kind(Model, S, P, O, Deps, Kind),
    (   var(Template),
        anchored(Kind, Template, S, O)
    ->  Anchored = true
    ;   Anchored = false
    ).

%   pattern_kind(+Model, +S, +P, +O, +Deps, -Kind): how the instances a
%   change creates are found (see the module doc).  A type with both
%   ends unbound is evaluated in full: solved unbound it only ranges
%   over individuals, while a seeded subject could be a class.  So is a
%   pattern whose subject and object are one variable (`?x near ?x`):
%   solved unbound, owl:sameAs substitution does not check that both
%   ends are the same individual, seeded it does.

pattern_kind(_, _, P, _, _, full) :-
    var(P),
    !.
pattern_kind(_, S, _, O, _, full) :-
    var(S),
    S == O,
    !.
pattern_kind(_, S, P, O, _, Kind) :-
    rdf_equal(P, rdf:type),
    !,
    (   var(S),
        var(O)
    ->  Kind = full
    ;   Kind = type
    ).
pattern_kind(_, _, P, _, _, full) :-
    special_predicate(P),
    !.
pattern_kind(_, _, _, _, any, full) :-
    !.
pattern_kind(Model, _, _, _, Deps, Kind) :-
    findall(T-TDeps, ( member(T, Deps),
                       oro_transitive_property(Model, T),
                       oro_pattern_dependencies(Model, [rdf(_, T, _)], TDeps)
                     ), Transitives),
    (   Transitives == []
    ->  Kind = step
    ;   Kind = trans(Transitives)
    ).

:- rdf_meta special_predicate(r).

special_predicate(rdfs:subClassOf).
special_predicate(rdfs:subPropertyOf).
special_predicate(owl:sameAs).

anchored(step, Template, S, O) :-
    (   Template == S
    ->  true
    ;   Template == O
    ).
anchored(type, Template, S, _) :-
    Template == S.

%   item_trigger(+Item, +Triples, -Q, -Anchor): a change of a triple
%   with predicate Q mentioning Anchor may change the pattern of Item.

item_trigger(item(I, Kind, Deps, _), Triples, Q, Anchor) :-
    Deps \== any,
    nth1(I, Triples, rdf(S, _, O)),
    member(Q, Deps),
    item_anchor(Kind, Q, S, O, Anchor).

item_anchor(step, _, S, O, Anchor) :-
    !,
    (   atom(S)
    ->  Anchor = res(S)
    ;   atom(O)
    ->  Anchor = res(O)
    ;   Anchor = none
    ).
item_anchor(type, Q, S, O, Anchor) :-
    !,
    (   atom(S)
    ->  Anchor = res(S)
    ;   atom(O),
        rdf_equal(Q, rdf:type)
    ->  Anchor = class(O)
    ;   Anchor = none
    ).
item_anchor(trans(Transitives), Q, S, O, Anchor) :-
    (   atom(S)
    ->  C = S
    ;   atom(O)
    ->  C = O
    ),
    !,
    (   member(_-TDeps, Transitives),
        ord_memberchk(Q, TDeps)
    ->  (   Anchor = chain
        ;   Anchor = chain(C)
        )
    ;   Anchor = res(C)
    ).
item_anchor(_, _, _, _, none).

%!  set_index(+Id, +Model, +Index) is det.
%
%   Install the index of watcher Id (see watcher_index/5).
%   New dependencies are added before the old ones go: writers read
%   them (touch/5) to decide whether to send a change, and must
%   never see a watcher with none.  Triggers and plans are the watcher
%   thread's own.

set_index(Id, Model, index(Deps, Triggers, Plan)) :-
    findall(D, watcher_dep(Model, D, Id), Old),
    forall(( member(D, Deps), \+ memberchk(D, Old) ),
           assertz(watcher_dep(Model, D, Id))),
    forall(( member(D, Old), \+ memberchk(D, Deps) ),
           retractall(watcher_dep(Model, D, Id))),
    set_type_triggers(Id, Model, Triggers),
    retractall(watcher_trigger(_, _, _, _, Id)),
    forall(( member(Q-Anchor, Triggers),
             Anchor \= class(_)
           ),
           ( trigger_key(Model, Q, Anchor, Key),
             assertz(watcher_trigger(Key, Model, Q, Anchor, Id))
           )),
    retractall(watcher_plan(Id, _)),
    assertz(watcher_plan(Id, Plan)).

%   set_type_triggers(+Id, +Model, +Triggers): the triggers of watcher Id
%   on rdf:type, which the writers read too (type_filter/3): a class(C)
%   anchor as watcher_type_class(C, Model, Id) (class_watcher/4, the
%   only place class anchors are kept), any other as
%   watcher_type_open(Model, Id).  New facts are added before stale ones
%   go, as for the dependencies.

set_type_triggers(Id, Model, Triggers) :-
    rdf_equal(rdf:type, Type),
    findall(C, member(Type-class(C), Triggers), Classes0),
    sort(Classes0, Classes),
    (   member(Type-Anchor, Triggers),
        Anchor \= class(_)
    ->  Open = true
    ;   Open = false
    ),
    (   Open == true,
        \+ watcher_type_open(Model, Id)
    ->  assertz(watcher_type_open(Model, Id))
    ;   true
    ),
    forall(( member(C, Classes),
             \+ watcher_type_class(C, Model, Id)
           ),
           assertz(watcher_type_class(C, Model, Id))),
    forall(( watcher_type_class(C, Model, Id),
             \+ ord_memberchk(C, Classes)
           ),
           retractall(watcher_type_class(C, Model, Id))),
    (   Open == false
    ->  retractall(watcher_type_open(Model, Id))
    ;   true
    ).

%!  trigger_key(+Model, +Q, +Anchor, -Key) is det.
%
%   Key is the hash under which watcher_trigger/5 keeps the triggers of
%   Model on predicate Q with Anchor.

trigger_key(Model, Q, Anchor, Key) :-
    term_hash(t(Model, Q, Anchor), Key).
