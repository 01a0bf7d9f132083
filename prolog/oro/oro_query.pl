:- module(oro_query,
          [ oro_solve/2,                % +Model, +Patterns
            oro_pattern_holds/2,        % +Model, +Pattern
            oro_find_values/4,          % +Model, ?Template, +Patterns, -Values
            oro_with_time_limit/1       % :Goal
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(settings)).
:- use_module(library(time)).
:- use_module(library(pairs)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(error)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_store), [oro_resolve_model/2]).
:- use_module(library(oro/oro_names), [oro_resource/2, oro_object/2]).

/** <module> Query: conjunctive patterns over the inference closure

A pattern is a term rdf(S, P, O) whose arguments are IRIs, literals or
Prolog variables; a list of patterns is a basic graph pattern whose
variables are shared.  oro_solve/2 enumerates its solutions over the
inference closure of a model (oro_holds/4), evaluating at each step
the pattern that is cheapest given the variables bound so far, so a
query with several patterns starts from its most selective one and
does not scan.

Every question that joins patterns (find with several patterns, every
SPARQL query) runs within the setting `oro_query:time_limit` (seconds,
default 5; 0 for none): a join of unbound patterns can take hours, and
must not hold a server worker and a core that long.  Past the limit,
the question stops with
`error(resource_error(oro_query_time_limit(Seconds)), _)`.  A single
pattern, and check (whose patterns share no variable), cost at most a
scan of what they match, and run without a limit.

A SPARQL query is limited by an alarm of library(time)
(oro_with_time_limit/1), whose thread is woken twice a call: on the
project's VM, two thread switches that cost a `check` over the socket
more than the check itself.  A find of several patterns does without:
oro_find_values/4 reads the clock after each solution of each pattern
that has a variable, and stops past its deadline.  Between two
readings it evaluates one such pattern, which costs at most a scan,
and checks of ground patterns, at most one per pattern; so it stops at
most that late.
*/

:- setting(time_limit, number, 5,
           'Maximum time (seconds) one join of patterns (find with \c
            several patterns, SPARQL query) may run; 0 for no limit').

:- meta_predicate oro_with_time_limit(0).

%!  oro_with_time_limit(:Goal) is semidet.
%
%   Run Goal once, within the `time_limit` setting.
%
%   @error resource_error(oro_query_time_limit(Seconds)) if Goal runs
%          longer.

oro_with_time_limit(Goal) :-
    setting(time_limit, Limit),
    (   Limit =< 0
    ->  once(Goal)
    ;   catch(call_with_time_limit(Limit, Goal),
              time_limit_exceeded,
              throw(error(resource_error(oro_query_time_limit(Limit)), _)))
    ).

%!  oro_solve(+Model, +Patterns) is nondet.
%
%   Bind the variables of Patterns (a list of rdf(S,P,O)) so that every
%   pattern holds in Model.  Solutions may repeat when several
%   derivations exist; use oro_find/4 for distinct answers.
%
%   @error existence_error(agent, Model) for an unknown model.
%   @error type_error(oro_pattern, Pattern) for a pattern that is not
%          rdf(S,P,O) (text patterns are for oro_check/2 and
%          oro_find/4, which name their variables).

oro_solve(Model0, Patterns0) :-
    must_be(list, Patterns0),
    maplist(public_pattern, Patterns0, Patterns),
    oro_resolve_model(Model0, Model),
    oro_with_shared_schema(Model, Key,
                           solve_normal(Patterns, Key, Model, none)).

public_pattern(Pattern0, Pattern) :-
    (   nonvar(Pattern0),
        Pattern0 = rdf(_, _, _)
    ->  normal_pattern(Pattern0, Pattern)
    ;   must_be(nonvar, Pattern0),
        type_error(oro_pattern, Pattern0)
    ).

%   solve(+Patterns, +Model, +Deadline): oro_solve/2, stopping past
%   Deadline (see deadline/1).  The patterns' names are normalised once
%   and the schema tables found once, for the whole join, in a pinned
%   region (oro_with_shared_schema/3) so that a schema change meanwhile
%   does not free them; what their variables are bound to comes from
%   the store, normal already (oro_holds_keyed/5).  The clock is read
%   after each solution of a pattern with a variable: a ground pattern
%   is a check, whose cost is bounded.

solve(Patterns0, Model, Deadline) :-
    maplist(normal_pattern, Patterns0, Patterns),
    oro_with_shared_schema(Model, Key,
                           solve_normal(Patterns, Key, Model, Deadline)).

normal_pattern(rdf(S0, P0, O0), rdf(S, P, O)) :-
    oro_resource(S0, S),
    oro_resource(P0, P),
    oro_object(O0, O).

solve_normal([], _, _, _) :-
    !.
solve_normal(Patterns, Key, Model, Deadline) :-
    cheapest(Patterns, Pattern, Rest),
    Pattern = rdf(S, P, O),
    (   ground(Pattern)
    ->  oro_holds_keyed(Key, Model, S, P, O)
    ;   oro_holds_keyed(Key, Model, S, P, O),
        in_time(Deadline)
    ),
    solve_normal(Rest, Key, Model, Deadline).

%   deadline(-Deadline): `none`, or deadline(Time, Limit) when the
%   `time_limit` setting is Limit seconds from now.

deadline(Deadline) :-
    setting(time_limit, Limit),
    (   Limit =< 0
    ->  Deadline = none
    ;   get_time(Now),
        Time is Now + Limit,
        Deadline = deadline(Time, Limit)
    ).

in_time(none) :-
    !.
in_time(deadline(Time, Limit)) :-
    get_time(Now),
    (   Now =< Time
    ->  true
    ;   throw(error(resource_error(oro_query_time_limit(Limit)), _))
    ).

%!  oro_pattern_holds(+Model, +Pattern) is semidet.
%
%   Pattern (rdf(S,P,O), possibly with variables) has at least one
%   solution in Model.  Variables are left unbound.

oro_pattern_holds(Model, rdf(S, P, O)) :-
    \+ \+ oro_holds(Model, S, P, O).

%!  oro_find_values(+Model, ?Template, +Patterns, -Values) is det.
%
%   Values is the ordered set of the distinct instantiations of
%   Template over the solutions of Patterns, leaving out those holding
%   a blank node or an unbound variable.  The patterns that share no
%   variable with Template, even through other patterns, are solved
%   once, for one solution.
%
%   @error resource_error(oro_query_time_limit(Seconds)) past the
%          `time_limit` setting, for two patterns or more.

oro_find_values(Model, Template, Patterns, Values) :-
    (   Patterns = [Pattern0]
    ->  normal_pattern(Pattern0, rdf(S, P, O)),
        oro_holds_bag(Model, Template, S, P, O, Values0)
    ;   deadline(Deadline),
        term_variables(Template, Vars),
        linked_patterns(Vars, Patterns, Linked, Others),
        (   forall(pattern_group(Others, Group),
                   once(solve(Group, Model, Deadline)))
        ->  findall(Template, solve(Linked, Model, Deadline), Values0)
        ;   Values0 = []
        )
    ),
    sort(Values0, Values1),
    usable_values(Values1, Values).

%   linked_patterns(+Vars, +Patterns, -Linked, -Others): Linked are the
%   patterns that share a variable with Vars, directly or through other
%   patterns; Others share none.  The values of Template only depend on
%   Linked: each group of Others (see pattern_group/2) only needs one
%   solution, not one for each solution of the rest.  Enumerating them
%   all would multiply the solutions (a find of `?x rdf:type Cup` with
%   `?h rdf:type Human` and `?r rdf:type Robot`: cups x humans x
%   robots).

linked_patterns(Vars, Patterns, Linked, Others) :-
    partition(shares_variable(Vars), Patterns, Direct, Rest),
    (   Direct == []
    ->  Linked = [],
        Others = Rest
    ;   term_variables(Vars-Direct, Vars1),
        linked_patterns(Vars1, Rest, Indirect, Others),
        append(Direct, Indirect, Linked)
    ).

shares_variable(Vars, Pattern) :-
    term_variables(Pattern, PatternVars),
    member(V, PatternVars),
    member(W, Vars),
    V == W,
    !.

%   pattern_group(+Patterns, -Group) is nondet: Group is a set of
%   Patterns linked by their variables, and no other pattern shares a
%   variable with it (a ground pattern is a group alone).

pattern_group([Pattern|Patterns], Group) :-
    term_variables(Pattern, Vars),
    linked_patterns(Vars, Patterns, Linked, Others),
    (   Group = [Pattern|Linked]
    ;   pattern_group(Others, Group)
    ).

%   usable_values(+Values0, -Values): Values0 less the values holding
%   a blank node or an unbound variable.  The usual value, an IRI, is
%   decided by one test.

usable_values([], []).
usable_values([Value|Values0], Values) :-
    (   atom(Value)
    ->  (   rdf_is_bnode(Value)
        ->  Values = Values1
        ;   Values = [Value|Values1]
        )
    ;   unusable_value(Value)
    ->  Values = Values1
    ;   Values = [Value|Values1]
    ),
    usable_values(Values0, Values1).

unusable_value(Value) :-
    \+ ground(Value),
    !.
unusable_value(Value) :-
    sub_term(Sub, Value),
    atom(Sub),
    rdf_is_bnode(Sub),
    !.

%   cheapest(+Patterns, -Best, -Rest): pick the pattern expected to
%   have the fewest solutions with the current bindings.

cheapest([Pattern], Pattern, []) :-
    !.
cheapest(Patterns, Best, Rest) :-
    map_list_to_pairs(cost, Patterns, Keyed),
    keysort(Keyed, [_-Best|_]),
    without(Patterns, Best, Rest).

%   without(+List, +Elem, -Rest): Rest is List less Elem, compared by
%   identity (unifying could merge two patterns that share variables).

without([H|T], X, Rest) :-
    (   H == X
    ->  Rest = T
    ;   Rest = [H|Rest1],
        without(T, X, Rest1)
    ).

cost(rdf(S, P, O), Cost) :-
    (   nonvar(S), nonvar(O)
    ->  Cost = 1
    ;   nonvar(S)
    ->  Cost = 10
    ;   nonvar(O)
    ->  object_cost(P, O, Cost)
    ;   nonvar(P)
    ->  predicate_cost(P, Cost)
    ;   Cost = 1.0e12
    ).

object_cost(P, O, Cost) :-
    (   O = literal(_)
    ->  predicate_cost(P, Cost0),
        Cost is 50 + Cost0/100
    ;   rdf_equal(P, rdf:type)
    ->  rdf_estimate_complexity(_, P, O, N),
        Cost is 100 + N
    ;   Cost = 20
    ).

predicate_cost(P, Cost) :-
    (   var(P)
    ->  Cost = 1.0e9
    ;   rdf_estimate_complexity(_, P, _, N)
    ->  Cost is 1000 + N
    ;   Cost = 1000
    ).
