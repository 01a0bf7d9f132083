:- module(oro_explain,
          [ oro_explain/3,              % +Model, +Statement, -Explanation
            oro_explain_conflict/2,     % +Model, -Conflicts
            oro_explain_conflict/3      % +Model, +Conflict, -Explanation
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(pairs)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/questions/oro_consistency)).

/** <module> Explanations: why a statement holds, why a model is inconsistent

oro_explain/3 answers, for a statement in the inference closure of a
model, the asserted statements and the schema axioms it rests on:

    ?- oro_explain(myself, "gorilla rdf:type Animal", E).
    E = explanation(rdf(oro:gorilla, rdf:type, oro:'Animal'),
                    [fact(rdf(oro:gorilla, rdf:type, oro:'Monkey'),
                          ontology('oro:ontology#1'))],
                    [rdf(oro:'Monkey', rdfs:subClassOf, oro:'Animal')]).

An explanation is explanation(Statement, Facts, Axioms):

  - Statement is the statement asked, rdf(S, P, O);
  - Facts is the ordered set of the asserted statements used, each
    fact(rdf(S, P, O), Origin) with Origin `profile(Profile)` (the
    model's graph of memory profile `longterm`, `shortterm` or
    `episodic`) or `ontology(Graph)` (a graph of the ontology layer);
  - Axioms is the ordered set of the schema triples used
    (rdfs:subClassOf, rdfs:domain, owl:inverseOf, a property's
    rdf:type owl:TransitiveProperty, ...).  An anonymous class
    (restriction, intersection, ...) comes with all the triples that
    define it, RDF list cells included, so the set stands on its own.

owl:sameAs and owl:differentFrom statements are facts like any other.
An explanation is one derivation, not all of them: the first one found
trying the simplest rules first (asserted, then sub-classes and
sub-properties, domains and ranges, class expressions, chains, then
transitivity).

oro_explain_conflict/2 answers, for an inconsistent model, the
conflicts (oro_conflict/2) with for each a *minimal* set of facts that
together with the axioms listed contradict the schema: conflict(Conflict,
Facts, Axioms), Facts minimal in the sense that removing any one of them
leaves no derivation of that conflict from the others (each is tried in
turn, the rest re-derived).

Explanations re-derive the statement with a proof-recording search
written for this module; oro_holds/4 and oro_type/3 stay as they are
and serve as an oracle: a sub-goal is only tried if it holds, so the
search does not wander.  The search carries the goals in progress and
gives up on a goal that is a variant of one of them, or nested more
than 64 deep.
*/

:- discontiguous
    rule/4.

:- rdf_meta
    oro_explain_conflict(+, t, -).

max_conflicts(20).
max_depth(64).

%!  oro_explain(+Model, +Statement, -Explanation) is semidet.
%
%   Explanation (see the module doc) tells why Statement (text, as in
%   the protocol, or rdf(S, P, O)) holds in Model; fails if it does
%   not.  If it holds by a derivation this module cannot replay,
%   Explanation is unexplained(rdf(S, P, O)).
%
%   @error syntax_error(oro_statement_incomplete(Text)) for a pattern.

oro_explain(Model0, Statement, Explanation) :-
    oro_resolve_model(Model0, Model),
    must_be(nonvar, Statement),
    oro_statements([Statement], [Triple], _),
    (   ground(Triple)
    ->  true
    ;   format(string(Text), "~w", [Statement]),
        throw(error(syntax_error(oro_statement_incomplete(Text)), _))
    ),
    Triple = rdf(S, P, O),
    oro_holds(Model, S, P, O),
    (   prove_goals([holds(S, P, O)], Model, all, Leaves)
    ->  leaves_explanation(Model, Leaves, Facts, Axioms),
        Explanation = explanation(Triple, Facts, Axioms)
    ;   Explanation = unexplained(Triple)
    ).

%!  oro_explain_conflict(+Model, -Conflicts) is det.
%
%   Conflicts is the list of conflicts of Model (among the first 20 of
%   oro_conflict/2), each conflict(Conflict, Facts, Axioms) with Facts
%   a minimal set of facts in conflict.  A conflict whose facts include
%   those of another one is left out, and of conflicts resting on the
%   same facts only the last is kept.  Conflicts is `[]` for a
%   consistent model.

oro_explain_conflict(Model0, Conflicts) :-
    oro_resolve_model(Model0, Model),
    max_conflicts(Max),
    findall(C, limit(Max, oro_conflict(Model, C)), Cs),
    findall(E, ( member(C, Cs),
                 oro_explain_conflict(Model, C, E)
               ), Es),
    smallest_sets(Es, Es, Conflicts).

%   smallest_sets(+Es, +All, -Kept): Es less those whose facts include
%   the facts of another one of All (a conflict about kk owl:sameAs
%   gorilla that rests on gorilla's conflict), and less repeated fact
%   sets.

smallest_sets([], _, []).
smallest_sets([E|Es], All, Kept) :-
    E = conflict(_, Facts, _),
    (   member(conflict(_, Other, _), All),
        Other \== Facts,
        ord_subset(Other, Facts)
    ->  Kept = Kept1
    ;   Es \== [],
        memberchk(conflict(_, Facts, _), Es)
    ->  Kept = Kept1
    ;   Kept = [E|Kept1]
    ),
    smallest_sets(Es, All, Kept1).

%!  oro_explain_conflict(+Model, +Conflict, -Explanation) is semidet.
%
%   Explanation is conflict(Conflict, Facts, Axioms) for one conflict of
%   oro_conflict/2, Facts minimal; fails if Conflict does not hold.

oro_explain_conflict(Model0, Conflict, conflict(Conflict, Facts, Axioms)) :-
    oro_resolve_model(Model0, Model),
    must_be(callable, Conflict),
    conflict_premises(Conflict, Model, Goals, Axioms0),
    prove_goals(Goals, Model, all, Leaves0),
    leaves_facts(Leaves0, Facts0),
    minimise(Facts0, Goals, Model, Leaves0, Leaves),
    leaves_explanation(Model, Leaves, Facts, Axioms1),
    sort(Axioms0, Axioms2),
    ord_union(Axioms2, Axioms1, Axioms).

%   minimise(+Facts, +Goals, +Model, +Leaves0, -Leaves): drop each fact
%   in turn and keep the result if Goals can still be derived from the
%   others alone.

minimise(Facts, Goals, Model, Leaves0, Leaves) :-
    minimise(Facts, Facts, Goals, Model, Leaves0, Leaves).

minimise([], _, _, _, Leaves, Leaves).
minimise([F|Fs], Current, Goals, Model, Leaves0, Leaves) :-
    (   ord_memberchk(F, Current),
        ord_del_element(Current, F, Allowed),
        prove_goals(Goals, Model, Allowed, Leaves1)
    ->  leaves_facts(Leaves1, Current1),
        minimise(Fs, Current1, Goals, Model, Leaves1, Leaves)
    ;   minimise(Fs, Current, Goals, Model, Leaves0, Leaves)
    ).

leaves_facts(Leaves, Facts) :-
    findall(T, member(fact(T), Leaves), Facts0),
    sort(Facts0, Facts).

leaves_explanation(Model, Leaves, Facts, Axioms) :-
    leaves_facts(Leaves, Triples),
    maplist(fact_origin(Model), Triples, Facts0),
    sort(Facts0, Facts),
    findall(A, member(axiom(A), Leaves), Axioms0),
    sort(Axioms0, Axioms).

fact_origin(Model, rdf(S, P, O), fact(rdf(S, P, O), Origin)) :-
    (   rdf(S, P, O, Source),
        source_graph(Source, Graph),
        graph_origin(Graph, Model, Origin)
    ->  true
    ;   Origin = unknown
    ).

source_graph(Graph:_, Graph) :-
    !.
source_graph(Graph, Graph).

graph_origin(Graph, Model, profile(Profile)) :-
    oro_graph_layer(Graph, Model, profile(Profile)),
    !.
graph_origin(Graph, _, ontology(Graph)) :-
    oro_ontology_graph(Graph).

		 /*******************************
		 *      CONFLICT PREMISES       *
		 *******************************/

%   conflict_premises(+Conflict, +Model, -Goals, -Axioms): the goals
%   whose derivation makes Conflict, and the axioms it contradicts.

conflict_premises(disjoint(X, C1, C2), Model, [type(X, C1), type(X, C2)], Axioms) :-
    disjointness_axioms(Model, C1, C2, Axioms).
conflict_premises(nothing(X), _, [type(X, Nothing)], []) :-
    rdf_equal(owl:'Nothing', Nothing).
conflict_premises(functional(P, X, V1, V2), _, Goals, [Axiom]) :-
    rdf_equal(owl:'FunctionalProperty', F),
    rdf_equal(rdf:type, Type),
    Axiom = rdf(P, Type, F),
    (   (   V1 = literal(_)
        ;   V2 = literal(_)
        )
    ->  Goals = [holds(X, P, V1), holds(X, P, V2)]
    ;   Goals = [holds(X, P, V1), holds(X, P, V2), different(V1, V2)]
    ).
conflict_premises(inverse_functional(P, V, X1, X2), _,
                  [holds(X1, P, V), holds(X2, P, V), different(X1, X2)],
                  [rdf(P, Type, F)]) :-
    rdf_equal(owl:'InverseFunctionalProperty', F),
    rdf_equal(rdf:type, Type).
conflict_premises(same_and_different(X, Y), _, [same(X, Y), different(X, Y)], []).
conflict_premises(irreflexive(P, X), _, [holds(X, P, X)], [rdf(P, Type, I)]) :-
    rdf_equal(owl:'IrreflexiveProperty', I),
    rdf_equal(rdf:type, Type).
conflict_premises(asymmetric(P, X, Y), _, [holds(X, P, Y), holds(Y, P, X)],
                  [rdf(P, Type, A)]) :-
    rdf_equal(owl:'AsymmetricProperty', A),
    rdf_equal(rdf:type, Type).
conflict_premises(disjoint_properties(P, Q, X, Y), Model,
                  [holds(X, P, Y), holds(X, Q, Y)], Axioms) :-
    rdf_equal(owl:propertyDisjointWith, DP),
    (   oro_asserted(Model, P, DP, Q)
    ->  Axioms = [rdf(P, DP, Q)]
    ;   oro_asserted(Model, Q, DP, P)
    ->  Axioms = [rdf(Q, DP, P)]
    ;   rdf_equal(owl:'AllDisjointProperties', All),
        members_axioms(Model, All, [P, Q], Axioms)
    ).

disjointness_axioms(Model, C1, C2, Axioms) :-
    (   rdf_equal(owl:disjointWith, D)
    ;   rdf_equal(owl:complementOf, D)
    ),
    (   oro_asserted(Model, C1, D, C2),
        A = rdf(C1, D, C2)
    ;   oro_asserted(Model, C2, D, C1),
        A = rdf(C2, D, C1)
    ),
    !,
    findall(T, ( member(C, [C1, C2]),
                 rdf_is_bnode(C),
                 description_triple(Model, C, T)
               ), Ts),
    sort([A|Ts], Axioms).
disjointness_axioms(Model, C1, C2, Axioms) :-
    rdf_equal(owl:'AllDisjointClasses', All),
    members_axioms(Model, All, [C1, C2], Axioms),
    !.
disjointness_axioms(_, _, _, []).

%   members_axioms(+Model, +AxiomClass, +Needed, -Axioms): the triples
%   of an owl:AllDisjointClasses (...) axiom listing all of Needed.

members_axioms(Model, Class, Needed, Axioms) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, Axiom, Type, Class),
    findall(T, description_triple(Model, Axiom, T), Ts),
    rdf_equal(rdf:first, First),
    findall(M, member(rdf(_, First, M), Ts), Ms),
    subset(Needed, Ms),
    !,
    sort(Ts, Axioms).

		 /*******************************
		 *        PROOF SEARCH          *
		 *******************************/

%   prove_goals(+Goals, +Model, +Allowed, -Leaves) is semidet: Leaves
%   (fact(Triple) and axiom(Triple) terms) derive every goal of Goals.
%   Allowed is `all` or the ordered set of the facts that may be used.

prove_goals(Goals, Model, Allowed, Leaves) :-
    foldl(prove_top(ctx(Model, Allowed, 0, [])), Goals, Leaves0, []),
    !,
    Leaves = Leaves0.

prove_top(Ctx, Goal, L0, L) :-
    prove(Goal, Ctx, L0, L).

%   prove(+Goal, +Ctx, -Leaves, ?Tail): a difference list of leaves.
%   Goals: holds(S, P, O), type(X, C), same(X, Y), different(X, Y),
%   sub(C, D), subprop(P, Q), way(P, Q, Dir).

prove(Goal, ctx(Model, Allowed, D, Anc), L0, L) :-
    max_depth(Max),
    D < Max,
    \+ ( member(G, Anc), G =@= Goal ),
    D1 is D + 1,
    rule(Goal, ctx(Model, Allowed, D1, [Goal|Anc]), L0, L).

ctx_model(ctx(Model, _, _, _), Model).

fact(rdf(S, P, O), ctx(Model, Allowed, _, _), [fact(rdf(S, P, O))|L], L) :-
    oro_asserted(Model, S, P, O),
    (   Allowed == all
    ->  true
    ;   ord_memberchk(rdf(S, P, O), Allowed)
    ),
    !.

axiom(Triple, [axiom(Triple)|L], L).

%   holds/3

rule(holds(S, P, O), Ctx, L0, L) :-
    rdf_equal(P, rdf:type),
    !,
    prove(type(S, O), Ctx, L0, L).
rule(holds(S, P, O), Ctx, L0, L) :-
    rdf_equal(P, owl:sameAs),
    !,
    prove(same(S, O), Ctx, L0, L).
rule(holds(S, P, O), Ctx, L0, L) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    prove(sub(S, O), Ctx, L0, L).
rule(holds(S, P, O), Ctx, L0, L) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    prove(subprop(S, O), Ctx, L0, L).
rule(holds(S, P, O), Ctx, L0, L) :-
    one_step(P, S, O, Ctx, L0, L).
rule(holds(S, P, O), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_property_way(Model, P, T, Dir),
    oro_transitive_property(Model, T),
    (   Dir == fwd
    ->  From = S,
        To = O
    ;   From = O,
        To = S
    ),
    atom(From),
    atom(To),
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'TransitiveProperty', Transitive),
    transitive_path(T, From, To, Ctx, L0, L1),
    axiom(rdf(T, Type, Transitive), L1, L2),
    prove(way(P, T, Dir), Ctx, L2, L).

%   one_step(+P, +S, +O, ...): an asserted or virtual edge implying
%   S P O, without transitivity.

one_step(P, S, O, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_property_way(Model, P, Q, Dir),
    (   Dir == fwd
    ->  S1 = S,
        O1 = O
    ;   S1 = O,
        O1 = S
    ),
    edge(Q, S1, O1, Ctx, L0, L1),
    prove(way(P, Q, Dir), Ctx, L1, L).

%   edge(+Q, +S, +O, ...): S Q O asserted (up to owl:sameAs), or
%   virtual (hasValue, chain).

edge(Q, S, O, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_same_individual(Model, S, S1),
    (   O = literal(_)
    ->  oro_asserted(Model, S1, Q, O1),
        O1 = literal(_),
        oro_literal_match(O, O1)
    ;   oro_same_individual(Model, O, O1),
        oro_asserted(Model, S1, Q, O1)
    ),
    fact(rdf(S1, Q, O1), Ctx, L0, L1),
    prove(same(S, S1), Ctx, L1, L2),
    (   O1 = literal(_)
    ->  L2 = L
    ;   prove(same(O, O1), Ctx, L2, L)
    ).
edge(Q, S, O, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_class_definition(Model, R, has_value(Q, V)),
    value_matches(Model, V, O),
    atom(S),
    oro_type(Model, S, R),
    prove(type(S, R), Ctx, L0, L1),
    definition_axioms(Model, R, L1, L2),
    (   V == O
    ->  L2 = L
    ;   O = literal(_)
    ->  L2 = L
    ;   prove(same(V, O), Ctx, L2, L)
    ).
edge(Q, S, O, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_property_chain(Model, Q, Links),
    atom(S),
    chain_path(Links, S, O, Ctx, L0, L1),
    rdf_equal(owl:propertyChainAxiom, Chain),
    oro_asserted(Model, Q, Chain, List),
    axiom(rdf(Q, Chain, List), L1, L2),
    description_axioms(Model, List, L2, L).

value_matches(Model, V, O) :-
    (   V = literal(_)
    ->  O = literal(_),
        oro_literal_match(O, V)
    ;   atom(O),
        oro_same_individual(Model, V, O),
        !
    ).

chain_path([Link], S, O, Ctx, L0, L) :-
    !,
    link_step(Link, S, O, Ctx, L0, L).
chain_path([Link|Links], S, O, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    link_candidates(Model, Link, S, Ys),
    member(Y, Ys),
    chain_holds(Model, Links, Y, O),
    link_step(Link, S, Y, Ctx, L0, L1),
    chain_path(Links, Y, O, Ctx, L1, L).

link_candidates(Model, inverse(P), S, Ys) :-
    !,
    findall(Y, oro_holds(Model, Y, P, S), Ys).
link_candidates(Model, P, S, Ys) :-
    findall(Y, ( oro_holds(Model, S, P, Y), atom(Y) ), Ys).

chain_holds(Model, [Link], S, O) :-
    !,
    link_holds(Model, Link, S, O).
chain_holds(Model, [Link|Links], S, O) :-
    link_candidates(Model, Link, S, Ys),
    member(Y, Ys),
    chain_holds(Model, Links, Y, O),
    !.

link_holds(Model, inverse(P), S, O) :-
    !,
    oro_holds(Model, O, P, S).
link_holds(Model, P, S, O) :-
    oro_holds(Model, S, P, O).

link_step(inverse(P), S, O, Ctx, L0, L) :-
    !,
    prove(holds(O, P, S), Ctx, L0, L).
link_step(P, S, O, Ctx, L0, L) :-
    prove(holds(S, P, O), Ctx, L0, L).

%   transitive_path(+T, +From, +To, ...): a path of one or more single
%   T steps, breadth first through the nodes that T reaches from From.
%   At least one step: when From == To (`x P x` through a cycle) the
%   path is the cycle back to From, never the empty path, which would
%   explain the statement by nothing.

transitive_path(T, From, To, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    findall(Y, oro_holds(Model, From, T, Y), Reach0),
    sort(Reach0, Reach),
    ord_memberchk(To, Reach),
    findall(Y-[From], ( member(Y, Reach),
                        single_step(Model, T, From, Y)
                      ), First),
    pairs_keys(First, Seen0),
    (   From == To
    ->  Seen = Seen0
    ;   Seen = [From|Seen0]
    ),
    bfs_path(First, T, To, Reach, Model, Seen, Path),
    path_steps(Path, T, Ctx, L0, L).

bfs_path([X-Back|_], _, To, _, _, _, Path) :-
    X == To,
    !,
    reverse([X|Back], Path).
bfs_path([X-Back|Queue], T, To, Reach, Model, Seen, Path) :-
    findall(Y-[X|Back], ( member(Y, Reach),
                          \+ memberchk(Y, Seen),
                          single_step(Model, T, X, Y)
                        ), Next),
    pairs_keys(Next, Ys),
    append(Seen, Ys, Seen1),
    append(Queue, Next, Queue1),
    bfs_path(Queue1, T, To, Reach, Model, Seen1, Path).

%   single_step(+Model, +T, +X, +Y): Y is one T step from X (an edge
%   implying T, asserted or virtual), checked with the oracle on the
%   edge's predicate.

single_step(Model, T, X, Y) :-
    oro_property_way(Model, T, Q, Dir),
    (   Dir == fwd
    ->  step_holds(Model, Q, X, Y)
    ;   step_holds(Model, Q, Y, X)
    ),
    !.

step_holds(Model, Q, S, O) :-
    oro_same_individual(Model, S, S1),
    oro_same_individual(Model, O, O1),
    oro_asserted(Model, S1, Q, O1),
    !.
step_holds(Model, Q, S, O) :-
    oro_class_definition(Model, R, has_value(Q, V)),
    value_matches(Model, V, O),
    oro_type(Model, S, R),
    !.
step_holds(Model, Q, S, O) :-
    oro_property_chain(Model, Q, Links),
    chain_holds(Model, Links, S, O),
    !.

path_steps([_], _, _, L, L) :-
    !.
path_steps([X, Y|Rest], T, Ctx, L0, L) :-
    one_step(T, X, Y, Ctx, L0, L1),
    !,
    path_steps([Y|Rest], T, Ctx, L1, L).

%   type/2

rule(type(X, C), Ctx, L0, L) :-
    rdf_equal(C, owl:'Thing'),
    !,
    ctx_model(Ctx, Model),
    oro_same_individual(Model, X, X1),
    individual_fact(Model, X1, Triple),
    fact(Triple, Ctx, L0, L1),
    prove(same(X, X1), Ctx, L1, L).
rule(type(X, C), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(rdf:type, Type),
    oro_same_individual(Model, X, X1),
    oro_asserted(Model, X1, Type, D),
    oro_subclass(Model, D, C),
    fact(rdf(X1, Type, D), Ctx, L0, L1),
    prove(same(X, X1), Ctx, L1, L2),
    prove(sub(D, C), Ctx, L2, L).
rule(type(X, C), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(rdfs:domain, Domain),
    oro_asserted(Model, P, Domain, D),
    atom(D),
    oro_subclass(Model, D, C),
    once(oro_holds(Model, X, P, Y)),
    axiom(rdf(P, Domain, D), L0, L1),
    prove(holds(X, P, Y), Ctx, L1, L2),
    prove(sub(D, C), Ctx, L2, L).
rule(type(X, C), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(rdfs:range, Range),
    oro_asserted(Model, P, Range, D),
    atom(D),
    oro_subclass(Model, D, C),
    once(oro_holds(Model, Y, P, X)),
    axiom(rdf(P, Range, D), L0, L1),
    prove(holds(Y, P, X), Ctx, L1, L2),
    prove(sub(D, C), Ctx, L2, L).
rule(type(X, C), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_class_definition(Model, D, Def),
    oro_subclass(Model, D, C),
    definition_member(Def, X, D, Ctx, L0, L1),
    definition_axioms(Model, D, L1, L2),
    prove(sub(D, C), Ctx, L2, L).
rule(type(X, C), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_class_definition(Model, R, all_values(Q, class(D))),
    oro_subclass(Model, D, C),
    oro_holds(Model, Z, Q, X),
    atom(Z),
    oro_type(Model, Z, R),
    prove(type(Z, R), Ctx, L0, L1),
    prove(holds(Z, Q, X), Ctx, L1, L2),
    definition_axioms(Model, R, L2, L3),
    prove(sub(D, C), Ctx, L3, L).

%   definition_member(+Definition, +X, +D, ...): X meets the definition
%   of the class D.

definition_member(has_value(Q, V), X, _, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_holds(Model, X, Q, V),
    prove(holds(X, Q, V), Ctx, L0, L).
definition_member(some_values(Q, Filler), X, _, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_holds(Model, X, Q, Y),
    filler_member(Filler, Model, Y),
    prove(holds(X, Q, Y), Ctx, L0, L1),
    (   Filler = class(F)
    ->  prove(type(Y, F), Ctx, L1, L)
    ;   L1 = L
    ).
definition_member(intersection(Ms), X, _, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    forall(member(M, Ms), oro_type(Model, X, M)),
    foldl(member_type(X, Ctx), Ms, L0, L).
definition_member(one_of(Xs), X, _, Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    oro_same_individual(Model, X, X1),
    memberchk(X1, Xs),
    prove(same(X, X1), Ctx, L0, L).

member_type(X, Ctx, M, L0, L) :-
    prove(type(X, M), Ctx, L0, L).

filler_member(thing, _, _).
filler_member(class(F), Model, Y) :-
    atom(Y),
    oro_type(Model, Y, F).
filler_member(datatype(DT, Facets), _, Y) :-
    oro_datatype_member(Y, datatype(DT, Facets)).

individual_fact(Model, X, rdf(X, P, O)) :-
    rdf_equal(rdf:type, P),
    oro_asserted(Model, X, P, O),
    \+ oro_meta_namespace(O).
individual_fact(Model, X, rdf(S, P, O)) :-
    (   oro_asserted(Model, X, P, O),
        S = X
    ;   oro_asserted(Model, S, P, X),
        O = X
    ),
    (   \+ oro_meta_namespace(P)
    ->  true
    ;   rdf_equal(P, owl:sameAs)
    ->  true
    ;   rdf_equal(P, owl:differentFrom)
    ).

%   same/2: a path of asserted owl:sameAs statements.

rule(same(X, Y), _, L, L) :-
    X == Y,
    !.
rule(same(X, Y), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(owl:sameAs, SameAs),
    oro_same_individual(Model, X, Y),
    graph_path(same_as_edge(Model, SameAs), X, Y, Path),
    foldl(same_fact(Ctx, SameAs), Path, L0, L).

same_as_edge(Model, SameAs, A, B, rdf(A, SameAs, B)) :-
    oro_asserted(Model, A, SameAs, B).
same_as_edge(Model, SameAs, A, B, rdf(B, SameAs, A)) :-
    oro_asserted(Model, B, SameAs, A).

same_fact(Ctx, _, Triple, L0, L) :-
    fact(Triple, Ctx, L0, L).

%   different/2: owl:differentFrom either way, or one owl:AllDifferent,
%   up to owl:sameAs.

rule(different(X, Y), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(owl:differentFrom, DF),
    oro_same_individual(Model, X, X1),
    oro_same_individual(Model, Y, Y1),
    (   oro_asserted(Model, X1, DF, Y1),
        Triple = rdf(X1, DF, Y1)
    ;   oro_asserted(Model, Y1, DF, X1),
        Triple = rdf(Y1, DF, X1)
    ),
    fact(Triple, Ctx, L0, L1),
    prove(same(X, X1), Ctx, L1, L2),
    prove(same(Y, Y1), Ctx, L2, L).
rule(different(X, Y), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    rdf_equal(owl:'AllDifferent', All),
    oro_same_individual(Model, X, X1),
    oro_same_individual(Model, Y, Y1),
    members_axioms(Model, All, [X1, Y1], Axioms),
    foldl(axiom_leaf, Axioms, L0, L1),
    prove(same(X, X1), Ctx, L1, L2),
    prove(same(Y, Y1), Ctx, L2, L).

axiom_leaf(A, L0, L) :-
    axiom(A, L0, L).

%   sub/2: a path of class axioms (rdfs:subClassOf, owl:equivalentClass
%   either way, an intersection to its members, a member to its union).

rule(sub(C, D), _, L, L) :-
    (   C == D
    ->  true
    ;   rdf_equal(D, owl:'Thing')
    ),
    !.
rule(sub(C, D), Ctx, L0, L) :-
    ctx_model(Ctx, Model),
    graph_path(class_edge(Model), C, D, Path),
    foldl(class_axioms(Model), Path, L0, L).

class_edge(Model, A, B, subclass(A, B)) :-
    rdf_equal(rdfs:subClassOf, Sub),
    oro_asserted(Model, A, Sub, B).
class_edge(Model, A, B, equivalent(A, B)) :-
    rdf_equal(owl:equivalentClass, Eq),
    oro_asserted(Model, A, Eq, B).
class_edge(Model, A, B, equivalent(B, A)) :-
    rdf_equal(owl:equivalentClass, Eq),
    oro_asserted(Model, B, Eq, A).
class_edge(Model, A, B, defined(A)) :-
    oro_class_definition(Model, A, intersection(Ms)),
    member(B, Ms).
class_edge(Model, A, B, defined(B)) :-
    oro_class_definition(Model, B, union(Ms)),
    memberchk(A, Ms).

class_axioms(Model, subclass(A, B), L0, L) :-
    rdf_equal(rdfs:subClassOf, Sub),
    axiom(rdf(A, Sub, B), L0, L1),
    bnode_axioms(Model, [A, B], L1, L).
class_axioms(Model, equivalent(A, B), L0, L) :-
    rdf_equal(owl:equivalentClass, Eq),
    axiom(rdf(A, Eq, B), L0, L1),
    bnode_axioms(Model, [A, B], L1, L).
class_axioms(Model, defined(C), L0, L) :-
    definition_axioms(Model, C, L0, L).

bnode_axioms(_, [], L, L).
bnode_axioms(Model, [C|Cs], L0, L) :-
    (   rdf_is_bnode(C)
    ->  description_axioms(Model, C, L0, L1)
    ;   L1 = L0
    ),
    bnode_axioms(Model, Cs, L1, L).

%   subprop/2 and way/3: paths of property axioms.

rule(subprop(P, Q), Ctx, L0, L) :-
    (   P == Q
    ->  L0 = L
    ;   ctx_model(Ctx, Model),
        graph_path(property_edge(Model), P, Q, Path),
        foldl(edge_axiom, Path, L0, L)
    ).
rule(way(P, Q, Dir), Ctx, L0, L) :-
    (   P == Q,
        Dir == fwd
    ->  L0 = L
    ;   ctx_model(Ctx, Model),
        graph_path(way_edge(Model), Q-Dir, P-fwd, Path),
        foldl(edge_axiom, Path, L0, L)
    ).

property_edge(Model, A, B, rdf(A, Sub, B)) :-
    rdf_equal(rdfs:subPropertyOf, Sub),
    oro_asserted(Model, A, Sub, B).
property_edge(Model, A, B, rdf(A, Eq, B)) :-
    rdf_equal(owl:equivalentProperty, Eq),
    oro_asserted(Model, A, Eq, B).
property_edge(Model, A, B, rdf(B, Eq, A)) :-
    rdf_equal(owl:equivalentProperty, Eq),
    oro_asserted(Model, B, Eq, A).

%   A Q-edge in direction Dir implies: an edge of a super-property in
%   the same direction, of an inverse in the other, of Q itself in the
%   other if Q is symmetric.

way_edge(Model, A-D, B-D, Axiom) :-
    property_edge(Model, A, B, Axiom).
way_edge(Model, A-D, B-F, rdf(A, Inv, B)) :-
    rdf_equal(owl:inverseOf, Inv),
    oro_asserted(Model, A, Inv, B),
    flip(D, F).
way_edge(Model, A-D, B-F, rdf(B, Inv, A)) :-
    rdf_equal(owl:inverseOf, Inv),
    oro_asserted(Model, B, Inv, A),
    flip(D, F).
way_edge(Model, A-D, A-F, rdf(A, Type, Sym)) :-
    rdf_equal(rdf:type, Type),
    rdf_equal(owl:'SymmetricProperty', Sym),
    oro_asserted(Model, A, Type, Sym),
    flip(D, F).

flip(fwd, bwd).
flip(bwd, fwd).

edge_axiom(Axiom, [axiom(Axiom)|L], L).

%!  graph_path(:Edge, +From, +To, -Labels) is semidet.
%
%   Labels are the labels of a shortest path from From to To, breadth
%   first over call(Edge, A, B, Label) (at most 10,000 nodes visited).

graph_path(Edge, From, To, Labels) :-
    graph_bfs([From-[]], Edge, To, [From], 10000, Labels0),
    reverse(Labels0, Labels).

graph_bfs([N-Back|_], _, To, _, _, Back) :-
    N == To,
    !.
graph_bfs([N-Back|Queue], Edge, To, Seen, Budget, Labels) :-
    Budget > 0,
    findall(M-[Label|Back], ( call(Edge, N, M, Label),
                              \+ memberchk(M, Seen)
                            ), Next0),
    sort(1, @<, Next0, Next),
    pairs_keys(Next, Ms),
    append(Seen, Ms, Seen1),
    append(Queue, Next, Queue1),
    Budget1 is Budget - 1,
    graph_bfs(Queue1, Edge, To, Seen1, Budget1, Labels).

		 /*******************************
		 *     ANONYMOUS CLASSES        *
		 *******************************/

%   definition_axioms(+Model, +Class, ...): the triples defining Class
%   if it is a blank node (with the nodes and lists it uses), or the
%   triple naming its definition (`C owl:intersectionOf L` ...).

definition_axioms(Model, C, L0, L) :-
    description_axioms(Model, C, L0, L).

description_axioms(Model, Node, L0, L) :-
    findall(T, description_triple(Model, Node, T), Ts0),
    sort(Ts0, Ts),
    foldl(axiom_leaf, Ts, L0, L).

%   description_triple(+Model, +Node, -Triple): a triple of a blank
%   node reachable from Node through blank nodes (for a named class,
%   its class-expression triples only).

description_triple(Model, Node, Triple) :-
    description_triples(Model, [Node], [], Triples),
    member(Triple, Triples).

description_triples(_, [], _, []).
description_triples(Model, [N|Ns], Seen, Triples) :-
    (   memberchk(N, Seen)
    ->  description_triples(Model, Ns, Seen, Triples)
    ;   findall(rdf(N, P, O), node_triple(Model, N, P, O), Own),
        findall(O, ( member(rdf(_, _, O), Own),
                     atom(O),
                     rdf_is_bnode(O)
                   ), Next),
        append(Ns, Next, Queue),
        description_triples(Model, Queue, [N|Seen], Rest),
        append(Own, Rest, Triples)
    ).

node_triple(Model, N, P, O) :-
    (   rdf_is_bnode(N)
    ->  oro_asserted(Model, N, P, O)
    ;   expression_predicate(P),
        oro_asserted(Model, N, P, O)
    ).

:- rdf_meta expression_predicate(r).

expression_predicate(owl:intersectionOf).
expression_predicate(owl:unionOf).
expression_predicate(owl:oneOf).
expression_predicate(owl:onProperty).
expression_predicate(owl:hasValue).
expression_predicate(owl:someValuesFrom).
expression_predicate(owl:allValuesFrom).
