:- module(oro_sparql_algebra,
          [ annotate_query/2,           % +Query, -Annotated
            plan_goals/5,               % +Template, +Names, +Bound, +Ctx, -Order
            memo/4                      % +Key, +Ctx, -Value, :Goal
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(debug)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/sparql/oro_sparql_grammar), [conjunction/2, free_variables/2]).
:- use_module(library(oro/sparql/oro_sparql_functions), [eval_expr/4]).

/** <module> The SPARQL algebra, annotated and planned for evaluation

Before evaluation, the algebra of a query (oro_sparql_grammar) is
annotated: each pattern with the variables it is certain to bind, each
basic graph pattern turned into a template of Prolog variables, the
conjuncts of FILTERs placed in the basic graph patterns they test, and
operators over constants folded.  The planner orders the triple
patterns of a basic graph pattern, greedily, cheapest first given the
variables already bound, with rdf_db's estimates (see
oro_sparql_engine for the rules).
*/

		 /*******************************
		 *          ANNOTATION          *
		 *******************************/

%   Before evaluation each pattern P becomes p(Certain, Op), Certain
%   the ordered set of the variables bound in every solution of P, and
%   every basic graph pattern a template of Prolog variables.

%!  annotate_query(+Query, -Annotated) is det.
%
%   Annotated is the algebra Query prepared for oro_sparql_eval: each
%   pattern P becomes p(Certain, Op), Certain the ordered set of the
%   variables bound in every solution of P.

annotate_query(select(Proj0, D, P0, Mods0), select(Proj, D, P, Mods)) :-
    annotate(P0, P),
    maplist(annotate_item, Proj0, Proj),
    annotate_expr(Mods0, Mods).
annotate_query(ask(P0, Mods0), ask(P, Mods)) :-
    annotate(P0, P),
    annotate_expr(Mods0, Mods).
annotate_query(construct(T, P0, Mods0), construct(T, P, Mods)) :-
    annotate(P0, P),
    annotate_expr(Mods0, Mods).
annotate_query(describe(T, P0, Mods0), describe(T, P, Mods)) :-
    annotate(P0, P),
    annotate_expr(Mods0, Mods).

annotate_item(var(N), var(N)).
annotate_item(as(E0, N), as(E, N)) :-
    annotate_expr(E0, E).

annotate(bgp(Ts), p(Names, bgp(Id, Names, Template))) :-
    flag(oro_sparql_bgp, Id, Id + 1),
    bgp_template(Ts, Names, Template).
annotate(join(A0, B0), p(C, join(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(CA, _), B = p(CB, _),
    ord_union(CA, CB, C).
annotate(union(A0, B0), p(C, union(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(CA, _), B = p(CB, _),
    ord_intersection(CA, CB, C).
annotate(left_join(A0, B0, E0), p(C, left_join(A, B, E))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(C, _),
    annotate_expr(E0, E).
annotate(minus(A0, B0), p(C, minus(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(C, _).
annotate(filter(E0, A0), P) :-
    annotate(A0, A),
    annotate_expr(E0, E),
    push_filter(E, A, P).
annotate(extend(A0, N, E0), p(C, extend(A, N, E))) :-
    annotate(A0, A),
    A = p(C, _),
    annotate_expr(E0, E).
annotate(values(Vars, Rows), p(C, values(Rows))) :-
    sort(Vars, Sorted),
    include(bound_in_all(Rows), Sorted, C).
annotate(subselect(Q0), p([], subselect(Q, cache(none)))) :-
    annotate_query(Q0, Q).
annotate(graph(T, P0), p(C, graph(T, P))) :-
    annotate(P0, P),
    P = p(CP, _),
    (   T = var(N)
    ->  ord_add_element(CP, N, C)
    ;   C = CP
    ).

%   push_filter(+Expr, +Annotated, -Pattern): the conjuncts of a FILTER
%   over a basic graph pattern whose variables the pattern binds become
%   test goals of the pattern, run as soon as their variables are bound
%   (FILTER(A && B) is FILTER(A) FILTER(B), and a conjunct only reads
%   variables every solution binds, so testing it early changes
%   nothing but the work).  Conjuncts with EXISTS stay outside.

push_filter(E, A, P) :-
    A = p(C, Op),
    (   Op = bgp(Id, Names, t(PVars, Goals))
    ->  conjuncts(E, Es),
        partition(pushable(Names), Es, Push, Keep),
        pairs_keys_values(Map, Names, PVars),
        maplist(test_goal(Map), Push, Tests),
        append(Goals, Tests, Goals1),
        A1 = p(C, bgp(Id, Names, t(PVars, Goals1))),
        (   Keep == []
        ->  P = A1
        ;   conjunction(Keep, K),
            P = p(C, filter(K, A1))
        )
    ;   P = p(C, filter(E, A))
    ).

conjuncts(and(A, B), Es) :-
    !,
    conjuncts(A, EA),
    conjuncts(B, EB),
    append(EA, EB, Es).
conjuncts(E, [E]).

pushable(Names, E) :-
    \+ ( sub_term(X, E),
          compound(X),
          ( X = exists(_) ; X = not_exists(_) ; X = agg(_, _, _, _) )
        ),
    free_variables(E, Vars),
    ord_subset(Vars, Names).

test_goal(Map, E, test(E, Pairs)) :-
    free_variables(E, Vars),
    maplist(variable_pair(Map), Vars, Pairs).

variable_pair(Map, N, N-V) :-
    memberchk(N-V, Map).

bound_in_all(Rows, N) :-
    forall(member(Row, Rows), memberchk(N-_, Row)).

annotate_expr(exists(P0), exists(P)) :-
    !,
    annotate(P0, P).
annotate_expr(not_exists(P0), not_exists(P)) :-
    !,
    annotate(P0, P).
annotate_expr(const(T), const(T)) :-
    !.
annotate_expr(E0, E) :-
    compound(E0),
    !,
    E0 =.. [F|Args0],
    maplist(annotate_expr, Args0, Args),
    E1 =.. [F|Args],
    fold_constant(E1, E).
annotate_expr(E, E).

%   fold_constant(+E0, -E): an operator or function applied to constants
%   is evaluated once (if that raises an expression error it is left
%   for evaluation time, where it belongs to a solution).

fold_constant(E0, E) :-
    foldable(E0),
    E0 =.. [_|Args],
    forall(member(A, Args), constant_argument(A)),
    empty_assoc(Empty),
    eval_expr(E0, [], ctx(none, [], none, cache(Empty)), V),
    !,
    E = const(V).
fold_constant(E, E).

foldable(fn(Name, _)) :-
    \+ memberchk(Name, [if, coalesce, rand, uuid, struuid, bnode]).
foldable(cmp(_, _, _)).
foldable(add(_, _)).
foldable(sub(_, _)).
foldable(mul(_, _)).
foldable(divide(_, _)).
foldable(neg(_)).
foldable(pos(_)).
foldable(not(_)).

constant_argument(const(_)) :- !.
constant_argument(Name) :- atom(Name), !.
constant_argument(cast(_)) :- !.
constant_argument(iri(_)) :- !.
constant_argument(Args) :-
    is_list(Args),
    forall(member(A, Args), A = const(_)).

%   bgp_template(+Triples, -Names, -Template): Template is
%   t(Vars, Goals), Vars the Prolog variables standing for Names.

bgp_template(Ts, Names, t(PVars, Goals)) :-
    phrase(triples_variables(Ts), Names0),
    sort(Names0, Names),
    length(Names, N),
    length(PVars, N),
    pairs_keys_values(Map, Names, PVars),
    maplist(goal_template(Map), Ts, Goals).

triples_variables([]) --> [].
triples_variables([T|Ts]) -->
    { T =.. [_, S, P, O] },
    node_variable(S), node_variable(P), node_variable(O),
    triples_variables(Ts).

node_variable(var(N)) --> !, [N].
node_variable(_) --> [].

goal_template(Map, rdf(S0, P0, O0), rdf(S, P, O)) :-
    maplist(node_template(Map), [S0, P0, O0], [S, P, O]).
goal_template(Map, path(S0, Path, O0), path(S, Path, O)) :-
    node_template(Map, S0, S),
    node_template(Map, O0, O).

node_template(Map, var(N), V) :-
    !,
    memberchk(N-V, Map).
node_template(_, T, T).


%!  plan_goals(+Template, +Names, +Bound, +Ctx, -Order) is det.
%
%   Order lists the goals of the basic graph pattern Template (by
%   position) greedily, always the cheapest given the variables bound
%   so far.  While planning, a bound variable whose
%   value is not known yet is the atom '$bound'; constants of the query
%   are estimated by their actual counts.

plan_goals(Template, Names, Bound, Ctx, Order) :-
    copy_term(Template, t(PVars, Goals)),
    pairs_keys_values(Map, Names, PVars),
    maplist(mark_bound(Map), Bound),
    numbered(Goals, 1, Indexed),
    plan(Indexed, Ctx, Order),
    debug(oro(sparql), 'Plan ~q for ~q bound: ~q', [Order, Bound, Goals]).

numbered([], _, []).
numbered([G|Gs], I, [I-G|IGs]) :-
    I1 is I + 1,
    numbered(Gs, I1, IGs).

mark_bound(Map, N) :-
    memberchk(N-'$bound', Map).

plan([], _, []).
plan(Indexed, Ctx, [I|Order]) :-
    Indexed = [I0-G0|Rest0],
    goal_cost(G0, Ctx, C0),
    cheapest(Rest0, Ctx, I0-G0, C0, I-G),
    delete_index(Indexed, I, Rest),
    term_variables(G, Vars),
    maplist(=('$bound'), Vars),
    plan(Rest, Ctx, Order).

cheapest([], _, Best, _, Best).
cheapest([I-G|Gs], Ctx, Best0, C0, Best) :-
    goal_cost(G, Ctx, C),
    (   C < C0
    ->  cheapest(Gs, Ctx, I-G, C, Best)
    ;   cheapest(Gs, Ctx, Best0, C0, Best)
    ).

delete_index([J-G|T], I, Rest) :-
    (   J == I
    ->  Rest = T
    ;   Rest = [J-G|Rest1],
        delete_index(T, I, Rest1)
    ).

%   goal_cost(+Goal, +Ctx, -Cost): the expected number of solutions of
%   Goal, a part being unbound (a variable), bound to a value not known
%   yet ('$bound') or a constant.

goal_cost(rdf(S, P, O), Ctx, Cost) :-
    (   nonvar(S),
        S = literal(_)
    ->  Cost = 0
    ;   nonvar(S), nonvar(P), nonvar(O)
    ->  check_cost(P, O, Ctx, Cost)
    ;   ( var(P) ; P == '$bound' )
    ->  (   nonvar(S)
        ->  node_estimate(S, subject, N),
            Cost is 10 + N
        ;   nonvar(O)
        ->  node_estimate(O, object, N),
            Cost is 10 + N
        ;   Cost = 1.0e12
        )
    ;   \+ atom(P)
    ->  Cost = 0
    ;   rdf_equal(P, rdf:type)
    ->  (   O == '$bound'
        ->  Cost = 100
        ;   nonvar(O)
        ->  (   atom(O)
            ->  cached_cost(type(O), Ctx, Cost)
            ;   Cost = 0
            )
        ;   nonvar(S)
        ->  Cost = 12
        ;   cached_cost(predicate(P), Ctx, N),
            Cost is 2 * N + 1000
        )
    ;   cached_cost(predicate(P), Ctx, NP),
        (   nonvar(S)
        ->  cached_cost(fan_out(P), Ctx, F),
            (   S == '$bound'
            ->  Cost is 2 + min(NP, F)
            ;   rdf_estimate_complexity(S, _, _, NS),
                Cost is 2 + min(NP, min(F, NS))
            )
        ;   O == '$bound'
        ->  cached_cost(fan_in(P), Ctx, F),
            Cost is 2 + min(NP, F)
        ;   nonvar(O)
        ->  (   O = literal(_)
            ->  Cost is 2 + NP / 10
            ;   rdf_estimate_complexity(_, _, O, NO),
                Cost is min(NP, 2 + NO)
            )
        ;   Cost is NP + 100
        )
    ).
goal_cost(test(_, Pairs), _, Cost) :-
    (   ground(Pairs)
    ->  Cost = 0
    ;   Cost = 1.0e15
    ).
goal_cost(path(S, _, O), _, Cost) :-
    (   nonvar(S), nonvar(O)
    ->  Cost = 20
    ;   ( nonvar(S) ; nonvar(O) )
    ->  Cost = 200
    ;   Cost = 1.0e10
    ).

node_estimate('$bound', _, 20) :- !.
node_estimate(X, Position, N) :-
    (   atom(X)
    ->  (   Position == subject
        ->  rdf_estimate_complexity(X, _, _, N)
        ;   rdf_estimate_complexity(_, _, X, N)
        )
    ;   N = 100
    ).

%   check_cost(+P, +O, +Ctx, -Cost): a triple with all its parts bound
%   is a check.  Checks never add solutions, so they run before any
%   pattern that binds a variable (they cost between 1 and 2), in the
%   order that minimises the expected work: by c/(1-p), c the price of
%   a check (type checks go through the class hierarchy: 4, literal
%   checks compare values: 1.5, others 1) and p the chance it passes
%   (the share of P's triples with this object; 1/2 when the object is
%   not known yet).

check_cost(P, O, Ctx, Cost) :-
    (   P == '$bound'
    ->  Rank = 2
    ;   \+ atom(P)
    ->  Rank = 0
    ;   O = literal(_)
    ->  Rank is 1.5 / 0.5
    ;   rdf_equal(P, rdf:type)
    ->  (   O == '$bound'
        ->  Rank = 8
        ;   cached_cost(type(O), Ctx, NC),
            cached_cost(predicate(P), Ctx, NP),
            Rank is 4 / max(0.01, 1 - NC / (NP + 1))
        )
    ;   O == '$bound'
    ->  Rank = 2
    ;   cached_cost(predicate(P), Ctx, NP),
        rdf_estimate_complexity(_, P, O, NO),
        Rank is 1 / max(0.01, 1 - NO / (NP + 1))
    ),
    Cost is 1 + Rank / (Rank + 1).

%   memo(+Key, +Ctx, -Value, :Goal): Value of Key, computed by Goal once
%   per query.

:- meta_predicate memo(+, +, -, 0).

%!  memo(+Key, +Ctx, -Value, :Goal) is det.
%
%   Value is the value of Key in the per-query cache of the evaluation
%   context Ctx; Goal computes it (binding Value) on first use.

memo(Key, ctx(_, _, _, Cache), Value, Goal) :-
    arg(1, Cache, Assoc),
    (   get_assoc(Key, Assoc, Value0)
    ->  Value = Value0
    ;   call(Goal),
        arg(1, Cache, Assoc1),
        put_assoc(Key, Assoc1, Value, Assoc2),
        nb_setarg(1, Cache, Assoc2)
    ).

%   cached_cost(+Key, +Ctx, -Cost): estimates that depend on the
%   schema (sub-properties, sub-classes), computed once per query.
%   Only a model (an atom) has a schema closure: asserted(Model) and
%   graphs(Graphs) are estimated by their triples alone.

cached_cost(Key, ctx(ds(Model, _), _, _, Cache), Cost) :-
    arg(1, Cache, Assoc),
    (   get_assoc(Key, Assoc, Cost0)
    ->  Cost = Cost0
    ;   estimate(Key, Model, Cost),
        put_assoc(Key, Assoc, Cost, Assoc1),
        nb_setarg(1, Cache, Assoc1)
    ).

estimate(predicate(P), Model, N) :-
    aggregate_all(sum(N0),
                  ( (   Sub = P
                    ;   atom(Model),
                        oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_estimate_complexity(_, Sub, _, N0)
                  ),
                  N).
estimate(fan_out(P), Model, F) :-
    aggregate_all(sum(F0),
                  ( (   Sub = P
                    ;   atom(Model),
                        oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_current_predicate(Sub),
                    rdf_predicate_property(Sub, rdf_subject_branch_factor(F0))
                  ),
                  F).
estimate(fan_in(P), Model, F) :-
    aggregate_all(sum(F0),
                  ( (   Sub = P
                    ;   atom(Model),
                        oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_current_predicate(Sub),
                    rdf_predicate_property(Sub, rdf_object_branch_factor(F0))
                  ),
                  F).
estimate(type(C), Model, N) :-
    rdf_equal(rdf:type, Type),
    (   rdf_equal(C, owl:'Thing')
    ->  rdf_estimate_complexity(_, Type, _, N)
    ;   aggregate_all(sum(N0),
                      ( (   Sub = C
                        ;   atom(Model),
                            oro_subclass(Model, Sub, C),
                            Sub \== C
                        ),
                        rdf_estimate_complexity(_, Type, Sub, N0)
                      ),
                      N)
    ).

