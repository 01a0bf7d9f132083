:- module(oro_consistency,
          [ oro_consistent/1,           % +Model
            oro_conflict/2,             % +Model, -Conflict
            oro_consistent_with/2,      % +Model, +Statements
            oro_safe_add/4,             % +Model, +Statements, +Profile, -Accepted
            oro_declared_different/3    % +Model, ?X, ?Y
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(pairs)).
:- use_module(library(debug)).
:- use_module(oro_store).
:- use_module(oro_reason).
:- use_module(oro_parse).
:- use_module(oro_memory).

/** <module> Consistency: a robot must not believe a cow is a plant

A model is inconsistent when its inference closure contradicts an axiom
of its schema.  oro_conflict/2 finds the contradictions oro checks:

  - an individual in two disjoint classes (owl:disjointWith, either
    way, and the members of owl:AllDisjointClasses), or in a class and
    its owl:complementOf, or in owl:Nothing;
  - two different values of an owl:FunctionalProperty for one subject,
    or two different subjects with one value of an
    owl:InverseFunctionalProperty.  Literals differ when their values
    differ; individuals only when declared different (owl:differentFrom,
    owl:AllDifferent): OWL makes no unique-name assumption;
  - individuals both owl:sameAs and owl:differentFrom each other;
  - `x p x` for an owl:IrreflexiveProperty, `x p y` and `y p x` for an
    owl:AsymmetricProperty, and `x p y` with `x q y` for
    p owl:propertyDisjointWith q (or both in owl:AllDisjointProperties).

Types and values are those of the inference closure (oro_reason), so a
conflict through domains, ranges, sub-classes and the OWL 2 RL class
expressions (a hasValue restriction giving a second value of a
functional property, an intersection of disjoint classes, ...) is found
as well.  An inconsistent model stays usable: every question is still
answered over what is there; only safeAdd refuses to add to it.

## Cost

A full check (oro_consistent/1, checkConsistency) enumerates the
instances of each disjoint class and the values of each property with
a characteristic, linear in their number.  Its verdict is remembered
for the model and the rdf_db generation it was made at (rdf_generation/1
changes with every committed change), so asking again before anything
changed costs nothing.

safeAdd and checkConsistency(Statements) check *incrementally* when
the model is known to be consistent before the change: only the
individuals the new statements can affect are checked (their types,
their values and the values pointing to them).  The affected set is the
subjects and objects of the new statements (and their owl:sameAs
individuals), grown along what can carry a change to another
individual: the transitive properties that imply a property some check
or class expression looks at (the whole chain up and down), the
properties of someValuesFrom and allValuesFrom restrictions, property
chains and hasValue values.  A full check is made instead when a new
statement changes the schema (oro_store's schema triples) or declares
individuals different (owl:differentFrom, owl:AllDifferent,
owl:AllDisjointClasses, owl:members, owl:distinctMembers), or when
the affected set exceeds 5,000 individuals.

Measured by bench/bench_consistency.pl (common-sense ontology, the
bench world): a full check 7 ms at 10k asserted triples, 69 ms at 100k
(mostly enumerating the values of the functional properties hasColor
and isVisible); a remembered verdict 1 us; safeAdd of one statement
0.4 ms at 10k, 0.6 ms at 100k (median; p99 under 4 ms), whether
accepted or rejected; after a plain add, safeAdd first pays a full
check.

The verdict cache is this module's state: verdict/3 facts, written
under the `oro_consistency` mutex, only outside transactions (or, in
safeAdd, in the module's own transaction while it has changed nothing),
where the generation identifies exactly what the check saw.
*/

:- rdf_meta
    trigger(r, o).

:- dynamic
    verdict/3.                      % Model, Generation, Consistent

%!  oro_consistent(+Model) is semidet.
%
%   Model has no conflict.

oro_consistent(Model0) :-
    oro_resolve_model(Model0, Model),
    consistent_now(Model).

%!  oro_conflict(+Model, -Conflict) is nondet.
%
%   Conflict is a contradiction of Model: disjoint(X, C1, C2) (C1 @<
%   C2), nothing(X), functional(P, X, V1, V2), inverse_functional(P, V,
%   X1, X2), same_and_different(X, Y), irreflexive(P, X), asymmetric(P,
%   X, Y) or disjoint_properties(P, Q, X, Y) (P @< Q).

oro_conflict(Model0, Conflict) :-
    oro_resolve_model(Model0, Model),
    conflict(Model, Conflict).

		 /*******************************
		 *          FULL CHECK          *
		 *******************************/

conflict(Model, disjoint(X, C1, C2)) :-
    findall(A-B, ( oro_disjoint_classes(Model, A, B),
                   A @< B
                 ), Pairs0),
    sort(Pairs0, Pairs),
    findall(C, ( member(A-B, Pairs), ( C = A ; C = B ) ), Classes0),
    sort(Classes0, Classes),
    findall(C-Xs, ( member(C, Classes),
                    instances(Model, C, Xs)
                  ), ClassInstances),       % each class once
    member(C1-C2, Pairs),
    memberchk(C1-Xs1, ClassInstances),
    Xs1 \== [],
    memberchk(C2-Xs2, ClassInstances),
    ord_intersection(Xs1, Xs2, Both),
    member(X, Both),
    \+ rdf_is_bnode(X).
conflict(Model, nothing(X)) :-
    rdf_equal(owl:'Nothing', Nothing),
    instances(Model, Nothing, Xs),
    member(X, Xs),
    \+ rdf_is_bnode(X).
conflict(Model, functional(P, X, V1, V2)) :-
    characteristic(Model, functional, P),
    findall(X0-V, oro_holds(Model, X0, P, V), Pairs),  % ordered by X0, V
    shared_key(Pairs, X, Vs),
    two_different(Model, Vs, V1, V2).
conflict(Model, inverse_functional(P, V, X1, X2)) :-
    characteristic(Model, inverse_functional, P),
    findall(V0-X, oro_holds(Model, X, P, V0), Pairs0),
    msort(Pairs0, Pairs),
    shared_key(Pairs, V, Xs),
    two_different(Model, Xs, X1, X2).
conflict(Model, same_and_different(X, Y)) :-
    different_pairs(Model, Pairs),
    member(X-Y, Pairs),
    oro_same_individual(Model, X, Y).
conflict(Model, irreflexive(P, X)) :-
    characteristic(Model, irreflexive, P),
    oro_holds(Model, X, P, X).
conflict(Model, asymmetric(P, X, Y)) :-
    characteristic(Model, asymmetric, P),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, Y, P, X).
conflict(Model, disjoint_properties(P, Q, X, Y)) :-
    findall(A-B, ( oro_disjoint_properties(Model, A, B),
                   A @< B
                 ), Pairs0),
    sort(Pairs0, Pairs),
    member(P-Q, Pairs),
    oro_holds(Model, X, P, Y),
    oro_holds(Model, X, Q, Y).

instances(Model, C, Xs) :-
    findall(X, oro_type(Model, X, C), Xs).    % ordered: oro_holds sorts

characteristic(Model, Char, P) :-
    findall(P0, oro_property_characteristic(Model, P0, Char), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

%   shared_key(+Pairs, -Key, -Values): Key has two values or more in
%   the ordered Key-Value list Pairs; one linear scan, most keys having
%   one value.

shared_key([K-V|Pairs], Key, Values) :-
    same_key_values(Pairs, K, Vs, Rest),
    (   Vs \== [],
        Key = K,
        Values = [V|Vs]
    ;   shared_key(Rest, Key, Values)
    ).

same_key_values([K1-V|Pairs], K, [V|Vs], Rest) :-
    K1 == K,
    !,
    same_key_values(Pairs, K, Vs, Rest).
same_key_values(Pairs, _, [], Pairs).

%   two_different(+Model, +Values, -V1, -V2): two values of the list
%   that differ (V1 before V2).

two_different(Model, Values, V1, V2) :-
    append(_, [V1|Rest], Values),
    member(V2, Rest),
    V1 \== V2,
    different(Model, V1, V2),
    !.

different(Model, V1, V2) :-
    (   V1 = literal(_), V2 = literal(_)
    ->  \+ oro_literal_match(V1, V2)
    ;   V1 = literal(_)
    ->  true
    ;   V2 = literal(_)
    ->  true
    ;   oro_declared_different(Model, V1, V2)
    ).

%!  oro_declared_different(+Model, ?X, ?Y) is nondet.
%
%   X and Y, or individuals owl:sameAs them, are declared different
%   (owl:differentFrom either way, or members of one owl:AllDifferent).
%   Semidet when X and Y are bound; with X or Y unbound, enumerates the
%   declared pairs themselves, both ways.

oro_declared_different(Model0, X, Y) :-
    oro_resolve_model(Model0, Model),
    different_pairs(Model, Pairs),
    (   nonvar(X), nonvar(Y)
    ->  oro_same_individual(Model, X, X1),
        oro_same_individual(Model, Y, Y1),
        (   ord_memberchk(X1-Y1, Pairs)
        ->  true
        ;   ord_memberchk(Y1-X1, Pairs)
        ),
        !
    ;   member(A-B, Pairs),
        (   X-Y = A-B
        ;   X-Y = B-A
        )
    ).

different_pairs(Model, Pairs) :-
    rdf_equal(owl:differentFrom, DF),
    findall(A-B, ( oro_asserted(Model, A, DF, B)
                 ; all_different(Model, A, B)
                 ), Pairs0),
    sort(Pairs0, Pairs).

all_different(Model, A, B) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'AllDifferent', All),
    oro_asserted(Model, Axiom, Type, All),
    (   rdf_equal(owl:distinctMembers, P)
    ;   rdf_equal(owl:members, P)
    ),
    oro_asserted(Model, Axiom, P, List),
    rdf_list_members(Model, List, Members),
    append(_, [A|Rest], Members),
    member(B, Rest).

rdf_list_members(Model, List, Members) :-
    rdf_equal(rdf:nil, Nil),
    rdf_equal(rdf:first, First),
    rdf_equal(rdf:rest, Rest),
    list_members(Model, List, Nil, First, Rest, Members, 10000).

list_members(_, Nil, Nil, _, _, [], _) :- !.
list_members(Model, Cell, Nil, First, Rest, [H|T], Budget) :-
    Budget > 0,
    oro_asserted(Model, Cell, First, H),
    oro_asserted(Model, Cell, Rest, Next),
    !,
    Budget1 is Budget - 1,
    list_members(Model, Next, Nil, First, Rest, T, Budget1).
list_members(_, _, _, _, _, [], _).

		 /*******************************
		 *        VERDICT CACHE         *
		 *******************************/

%   consistent_now(+Model): a full check, or the verdict remembered for
%   the current generation.  The cache is used outside transactions
%   only: there the generation names exactly what is visible.

consistent_now(Model) :-
    (   \+ rdf_active_transaction(_),
        rdf_generation(Gen),
        integer(Gen)
    ->  consistent_at(Model, Gen)
    ;   \+ conflict(Model, _)
    ).

%   consistent_at(+Model, +Gen): Model is consistent at generation Gen
%   (what this thread sees now).

consistent_at(Model, Gen) :-
    (   verdict(Model, Gen, Verdict)
    ->  true
    ;   (   conflict(Model, _)
        ->  Verdict = false
        ;   Verdict = true
        ),
        remember(Model, Gen, Verdict)
    ),
    Verdict == true.

remember(Model, Gen, Verdict) :-
    with_mutex(oro_consistency,
               ( retractall(verdict(Model, _, _)),
                 assertz(verdict(Model, Gen, Verdict))
               )),
    debug(oro(consistency), 'Model ~q at generation ~q: consistent ~q',
          [Model, Gen, Verdict]).

%   own_generation(+Action, -Gen): inside the transaction of Action,
%   which has changed nothing yet and is the only one active, Gen is
%   the generation the thread sees.  Fails otherwise.

own_generation(Action, Gen) :-
    findall(T, rdf_active_transaction(T), [oro(Action)]),
    rdf_generation(Gen),
    integer(Gen).

consistent_before(Action, Model) :-
    (   own_generation(Action, Gen)
    ->  consistent_at(Model, Gen)
    ;   \+ conflict(Model, _)
    ).

%   After a commit: if the generation is exactly one more than Gen0
%   (nothing else committed meanwhile), remember Verdict for it.

remember_after(Model, Gen0, Verdict) :-
    (   integer(Gen0),
        \+ rdf_active_transaction(_),
        rdf_generation(Gen),
        integer(Gen),
        (   Gen =:= Gen0 + 1
        ;   Gen =:= Gen0
        )
    ->  remember(Model, Gen, Verdict)
    ;   true
    ).

		 /*******************************
		 *      INCREMENTAL CHECK       *
		 *******************************/

%   new_conflict(+Model, +Triples): Model, consistent before the
%   triples Triples were added to it, is not any more.

new_conflict(_, []) :-
    !,
    fail.
new_conflict(Model, Triples) :-
    (   member(rdf(_, P, O), Triples),
        (   oro_schema_triple(P, O)
        ;   trigger(P, O)
        )
    ->  debug(oro(consistency), 'Full check: schema or difference change', []),
        conflict(Model, _)
    ;   affected(Model, Triples, Affected)
    ->  checks(Model, Checks),
        member(X, Affected),
        individual_conflict(Model, Checks, X, _)
    ;   debug(oro(consistency), 'Full check: too many affected individuals', []),
        conflict(Model, _)
    ),
    !.

trigger(owl:differentFrom, _).
trigger(owl:distinctMembers, _).
trigger(owl:members, _).
trigger(rdf:type, owl:'AllDifferent').
trigger(rdf:type, owl:'AllDisjointClasses').
trigger(rdf:type, owl:'AllDisjointProperties').

max_affected(5000).

%   affected(+Model, +Triples, -Affected) is semidet: the individuals
%   whose types or values the triples may have changed; fails if there
%   are more than max_affected/1.

affected(Model, Triples, Affected) :-
    rdf_equal(rdf:type, Type),
    findall(X, ( member(rdf(S, P, O), Triples),
                 (   X0 = S
                 ;   P \== Type,
                     atom(O),
                     X0 = O
                 ),
                 oro_same_individual(Model, X0, X)
               ), Seeds0),
    sort(Seeds0, Seeds),
    spreading(Model, Spread),
    (   Spread = spread([], [], [], [], [])
    ->  Affected = Seeds
    ;   max_affected(Max),
        findall(X-seed, member(X, Seeds), Queue),
        spread(Queue, Model, Spread, Seeds, Max, Affected)
    ).

%   spreading(+Model, -Spread): what carries a change from an
%   individual to others: spread(Transitive, Some, All, Values, Chains)
%   with the transitive properties to follow both ways, the properties
%   to follow backwards (someValuesFrom) and forwards (allValuesFrom),
%   the resource values of hasValue restrictions, and the link
%   properties of chains with the chain length.

spreading(Model, spread(Ts, Somes, Alls, Values, Chains)) :-
    findall(P, sensitive_property(Model, P), Ps0),
    sort(Ps0, Ps),
    findall(T, ( member(P, Ps),
                 oro_property_way(Model, P, T, _),
                 oro_transitive_property(Model, T)
               ), Ts0),
    sort(Ts0, Ts),
    findall(Q, oro_class_definition(Model, _, some_values(Q, class(_))), Somes0),
    sort(Somes0, Somes),
    findall(Q, oro_class_definition(Model, _, all_values(Q, class(_))), Alls0),
    sort(Alls0, Alls),
    findall(V, ( oro_class_definition(Model, _, has_value(_, V)),
                 atom(V)
               ), Values0),
    sort(Values0, Values),
    findall(N-Links, ( oro_property_chain(Model, _, Links),
                       length(Links, N)
                     ), Chains0),
    sort(Chains0, Chains).

sensitive_property(Model, P) :-
    oro_property_characteristic(Model, P, _).
sensitive_property(Model, P) :-
    oro_disjoint_properties(Model, P, _).
sensitive_property(Model, P) :-
    oro_class_definition(Model, _, Def),
    arg(1, Def, P),
    atom(P),
    functor(Def, Name, 2),
    memberchk(Name, [has_value, some_values, all_values]).
sensitive_property(Model, P) :-
    oro_property_chain(Model, _, Links),
    member(Link, Links),
    (   Link = inverse(P)
    ->  true
    ;   P = Link
    ).

%   spread(+Queue, +Model, +Spread, +Seen, +Max, -Affected): breadth
%   first.  Queue holds X-How: `seed` individuals spread along
%   transitive properties, those reached that way do not (their chain
%   is the one already followed).

spread([], _, _, Seen, _, Seen).
spread([X-How|Queue], Model, Spread, Seen, Max, Affected) :-
    findall(Y-How1, neighbour(Model, Spread, How, X, Y, How1), Next0),
    sort(Next0, Next1),
    exclude(seen(Seen), Next1, Next),
    pairs_keys(Next, New0),
    sort(New0, New),
    ord_union(Seen, New, Seen1),
    length(Seen1, N),
    N =< Max,
    append(Queue, Next, Queue1),
    spread(Queue1, Model, Spread, Seen1, Max, Affected).

seen(Seen, Y-_) :-
    ord_memberchk(Y, Seen).

neighbour(Model, spread(Ts, _, _, _, _), seed, X, Y, closure) :-
    member(T, Ts),
    (   oro_holds(Model, Y, T, X)
    ;   oro_holds(Model, X, T, Y)
    ),
    atom(Y).
neighbour(Model, spread(_, Somes, _, _, _), _, X, Y, seed) :-
    member(Q, Somes),
    oro_holds(Model, Y, Q, X),
    atom(Y).
neighbour(Model, spread(_, _, Alls, _, _), _, X, Y, seed) :-
    member(Q, Alls),
    oro_holds(Model, X, Q, Y),
    atom(Y).
neighbour(_, spread(_, _, _, Values, _), _, _, Y, seed) :-
    member(Y, Values).
neighbour(Model, spread(_, _, _, _, Chains), _, X, Y, seed) :-
    member(N-Links, Chains),
    chain_neighbour(Model, Links, N, X, Y).

%   Anything within N link steps, either way, of X.

chain_neighbour(Model, Links, N, X, Y) :-
    findall(P, ( member(L, Links),
                 (   L = inverse(P)
                 ->  true
                 ;   P = L
                 )
               ), Ps0),
    sort(Ps0, Ps),
    chain_ball(Model, Ps, N, [X], [X], Ball),
    member(Y, Ball),
    Y \== X.

chain_ball(_, _, 0, _, Ball, Ball) :-
    !.
chain_ball(Model, Ps, N, Frontier, Ball0, Ball) :-
    findall(Y, ( member(X, Frontier),
                 member(P, Ps),
                 (   oro_holds(Model, X, P, Y)
                 ;   oro_holds(Model, Y, P, X)
                 ),
                 atom(Y)
               ), Ys0),
    sort(Ys0, Ys),
    ord_subtract(Ys, Ball0, New),
    ord_union(Ball0, New, Ball1),
    N1 is N - 1,
    (   New == []
    ->  Ball = Ball1
    ;   chain_ball(Model, Ps, N1, New, Ball1, Ball)
    ).

%   checks(+Model, -Checks): the axioms an individual is checked
%   against.

checks(Model, checks(Functional, InverseFunctional, Irreflexive,
                     Asymmetric, DisjointProperties)) :-
    findall(P, characteristic(Model, functional, P), Functional),
    findall(P, characteristic(Model, inverse_functional, P),
            InverseFunctional),
    findall(P, characteristic(Model, irreflexive, P), Irreflexive),
    findall(P, characteristic(Model, asymmetric, P), Asymmetric),
    findall(P-Q, oro_disjoint_properties(Model, P, Q), DisjointProperties0),
    sort(DisjointProperties0, DisjointProperties).

%   individual_conflict(+Model, +Checks, +X, -Conflict): a conflict
%   about X: its types, its values, the subjects sharing a value of X
%   or pointing to X by an inverse functional property.

individual_conflict(Model, _, X, Conflict) :-
    findall(C, oro_type(Model, X, C), Types),
    rdf_equal(owl:'Nothing', Nothing),
    (   ord_memberchk(Nothing, Types)
    ->  Conflict = nothing(X)
    ;   member(C1, Types),
        oro_disjoint_classes(Model, C1, C2),
        C1 @< C2,
        ord_memberchk(C2, Types),
        Conflict = disjoint(X, C1, C2)
    ).
individual_conflict(Model, checks(Fs, _, _, _, _), X, functional(P, X, V1, V2)) :-
    member(P, Fs),
    findall(V, oro_holds(Model, X, P, V), Vs),
    two_different(Model, Vs, V1, V2).
individual_conflict(Model, checks(_, IFs, _, _, _), X, inverse_functional(P, V, X1, X2)) :-
    member(P, IFs),
    (   V = X
    ;   oro_holds(Model, X, P, V)
    ),
    findall(Z, oro_holds(Model, Z, P, V), Zs),
    two_different(Model, Zs, X1, X2).
individual_conflict(Model, checks(_, _, Is, _, _), X, irreflexive(P, X)) :-
    member(P, Is),
    oro_holds(Model, X, P, X).
individual_conflict(Model, checks(_, _, _, As, _), X, Conflict) :-
    member(P, As),
    (   oro_holds(Model, X, P, Y),
        oro_holds(Model, Y, P, X)
    ->  msort([X, Y], [A, B]),
        Conflict = asymmetric(P, A, B)
    ).
individual_conflict(Model, checks(_, _, _, _, DPs), X, disjoint_properties(P, Q, X, Y)) :-
    member(P-Q, DPs),
    P @< Q,
    oro_holds(Model, X, P, Y),
    oro_holds(Model, X, Q, Y).

		 /*******************************
		 *        HYPOTHESES, ADDS      *
		 *******************************/

%!  oro_consistent_with(+Model, +Statements) is semidet.
%
%   Model is consistent and would stay so with Statements added: they
%   are added in a transaction that is always rolled back, so nothing
%   is kept and nobody sees them.  The check is incremental when Model
%   is known to be consistent.

oro_consistent_with(Model0, Statements) :-
    oro_resolve_model(Model0, Model),
    oro_statements(Statements, Triples, _),
    must_be(ground, Triples),
    catch(oro_store_write(check(Model), hypothesis(Model, Triples)),
          oro_hypothesis(Result),
          true),
    Result == true.

hypothesis(Model, Triples) :-
    (   consistent_before(check(Model), Model)
    ->  exclude(visible(Model), Triples, New),
        oro_store_assert(Model, Triples, longterm),
        (   new_conflict(Model, New)
        ->  throw(oro_hypothesis(false))
        ;   throw(oro_hypothesis(true))
        )
    ;   throw(oro_hypothesis(false))
    ).

%!  oro_safe_add(+Model, +Statements, +Profile, -Accepted) is det.
%
%   Add Statements to Model keeping it consistent (ORO's safeAdd): if
%   the model is consistent with all of them they are all added and
%   Accepted is `true`; otherwise each statement is tried in turn and
%   kept only if the model stays consistent, and Accepted is `false`.
%   If Model is inconsistent already, nothing is added.  One
%   transaction; the checks are incremental (see the module doc).

oro_safe_add(Model0, Statements, Profile0, Accepted) :-
    oro_resolve_model(Model0, Model),
    oro_memory_profile(Profile0, Profile),
    oro_statements(Statements, Triples, _),
    (   member(T, Triples), \+ ground(T)
    ->  format(string(Text), "~w", [T]),
        throw(error(syntax_error(oro_statement_incomplete(Text)), _))
    ;   true
    ),
    oro_store_write(safe_add(Model),
                    safe_add(Model, Triples, Profile, Result, Gen0)),
    (   Result == false
    ->  Accepted = false
    ;   remember_after(Model, Gen0, true),
        (   Result == true
        ->  Accepted = true
        ;   Accepted = false
        )
    ).

%   Result is `true`, `partly` (the model stays consistent, some
%   statements were rejected) or `false` (inconsistent before).  Gen0
%   is the generation before the change, if known.

safe_add(Model, Triples, Profile, Accepted, Gen0) :-
    (   own_generation(safe_add(Model), Gen)
    ->  Gen0 = Gen
    ;   true
    ),
    (   \+ consistent_before(safe_add(Model), Model)
    ->  Accepted = false
    ;   exclude(visible(Model), Triples, New),
        oro_store_assert(Model, Triples, Profile),
        (   \+ new_conflict(Model, New)
        ->  oro_memory_remember(Model, Profile, Triples),
            Accepted = true
        ;   oro_store_retract(Model, New),
            foldl(try_triple(Model, Profile), New, [], Kept),
            oro_memory_remember(Model, Profile, Kept),
            Accepted = partly
        )
    ).

visible(Model, rdf(S, P, O)) :-
    once(oro_asserted(Model, S, P, O)).

try_triple(Model, Profile, Triple, Kept0, Kept) :-
    (   visible(Model, Triple)
    ->  Kept = Kept0
    ;   oro_store_assert(Model, [Triple], Profile),
        (   new_conflict(Model, [Triple])
        ->  oro_store_retract(Model, [Triple]),
            Kept = Kept0
        ;   Kept = [Triple|Kept0]
        )
    ).
