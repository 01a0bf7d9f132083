:- module(oro_parse_budget,
          [ oro_parse_budget/1,         % :Goal
            bounded/2,                  % +Size, :Goal
            texts_size/2,               % +Texts, -Size
            chunk_chars/1,              % -N
            nesting_error/1             % +Max
          ]).
:- use_module(library(apply)).
:- use_module(library(settings)).

:- meta_predicate
    oro_parse_budget(0),
    bounded(+, 0).

/** <module> The limits of parsing: the parse budget and the nesting depth

This module owns what bounds the cost of parsing a request (see the
module doc of oro_parse, "Bounded cost"): the two settings, the CPU
budget of a request and the size of the chunks texts are scanned in.
The other parts of the parser call bounded/2 around the work of each
public predicate and nesting_error/1 where a depth passes the limit.

The settings keep the name they have always had, in the module users
configure, oro_parse (`oro_parse:max_nesting`,
`oro_parse:inference_limit`: the command line, config files and the
error texts use those names); they are declared here, with what
enforces them, so that no part of the parser depends on the module
that puts the parts together.

  - oro_parse_budget/1 opens the budget of a request.
  - bounded/2 runs a parse within what is left of it.
  - nesting_error/1 raises `resource_error(oro_nesting(Max))`.

The messages of both resource errors are defined here.
*/

:- setting(oro_parse:max_nesting, positive_integer, 32,
           'Deepest nesting of [ ] and of { } a request parameter may have').
:- setting(oro_parse:inference_limit, nonneg, 50000000,
           'Inferences the parsing of one request may take (a CPU budget \c
            that does not depend on the load: 50,000,000 is 2-14 s of \c
            CPU); 0 for no limit').

%!  chunk_chars(-N:positive_integer) is det.
%
%   Texts are scanned N characters at a time, so that a text full of
%   tracked characters does not make one string per character before
%   anything is decided.

chunk_chars(16384).

%   budget_chars(-N): a public predicate given a text of N characters
%   or more spends from the parse budget.

budget_chars(65536).

%!  oro_parse_budget(:Goal) is semidet.
%
%   Run Goal once with a parse budget of its own: the parsing done by
%   the predicates of oro_parse within Goal takes at most the
%   `inference_limit` setting in all (the server runs each request
%   so).  Outside such a Goal each public call has the whole limit.
%
%   @error resource_error(oro_parse_limit(Limit)) if the parsing within
%          Goal takes more.

oro_parse_budget(Goal) :-
    setting(oro_parse:inference_limit, Limit),
    (   nb_current(oro_parse_left, Old)
    ->  true
    ;   Old = none
    ),
    setup_call_cleanup(nb_setval(oro_parse_left, Limit),
                       once(Goal),
                       restore_budget(Old)).

restore_budget(none) :-
    !,
    nb_delete(oro_parse_left).
restore_budget(Old) :-
    nb_setval(oro_parse_left, Old).

%!  bounded(+Size:nonneg, :Goal) is semidet.
%
%   Run Goal once, the parse of texts of Size characters in all, within
%   what is left of the parse budget when Size is budget_chars/1 or
%   more (call_with_inference_limit/3, which costs no thread switch).
%
%   @error resource_error(oro_parse_limit(Limit)) if Goal takes more
%          than what is left.

bounded(Size, Goal) :-
    budget_chars(Min),
    (   Size < Min
    ->  call(Goal)
    ;   setting(oro_parse:inference_limit, Limit),
        Limit > 0
    ->  (   nb_current(oro_parse_left, Left0)
        ->  Left = Left0
        ;   Left = Limit
        ),
        statistics(inferences, I0),
        (   Left =< 0
        ->  Result = inference_limit_exceeded
        ;   call_with_inference_limit(once(Goal), Left, Result)
        ),
        (   Result == inference_limit_exceeded
        ->  throw(error(resource_error(oro_parse_limit(Limit)), _))
        ;   nb_current(oro_parse_left, _)
        ->  statistics(inferences, I1),
            Left1 is Left - (I1-I0),
            nb_setval(oro_parse_left, Left1)
        ;   true
        )
    ;   call(Goal)
    ).

%!  texts_size(+Texts:list, -Size:nonneg) is det.
%
%   Size is the number of characters of the atoms and strings in Texts
%   (other elements count for nothing).

texts_size(Texts, Size) :-
    foldl(add_text_size, Texts, 0, Size).

add_text_size(Text, Size0, Size) :-
    (   text(Text)
    ->  atom_length(Text, Length),
        Size is Size0 + Length
    ;   Size = Size0
    ).

text(Text) :-
    (   string(Text)
    ->  true
    ;   atom(Text)
    ).

%!  nesting_error(+Max:positive_integer).
%
%   Raise the error of brackets or braces nested deeper than Max (the
%   `max_nesting` setting); it never succeeds.
%
%   @error resource_error(oro_nesting(Max)), always.

nesting_error(Max) :-
    throw(error(resource_error(oro_nesting(Max)), _)).

:- multifile prolog:error_message//1.

prolog:error_message(resource_error(oro_nesting(Max))) -->
    [ 'Brackets or braces nested deeper than ~d levels'-[Max] ].
prolog:error_message(resource_error(oro_parse_limit(Limit))) -->
    [ 'The request took more than its parse budget (~D inferences)'-[Limit] ].
